// MagicaVoxel scene graphs: models placed by nTRN translations and every packed rotation (checked
// against rotation matrices built here from the format's description), instancing, nested
// groups, hidden nodes and layers, animation frames.
#include <gtest/gtest.h>

#include <array>
#include <map>
#include <set>

#include "luxel/voxel/vox_import.h"
#include "support/vox_writer.h"

namespace luxel::voxel {
namespace {

namespace vw = luxel::test::vox;
using V3 = std::array<std::int64_t, 3>;
using Matrix = std::array<std::array<int, 3>, 3>;

// The rotation byte as a matrix, from the format text: bits 0-1 the column of row 0's non-zero
// entry, bits 2-3 that of row 1, row 2 the remaining column; bits 4-6 the rows' signs.
bool matrixOf(int byte, Matrix& m) {
    const int c0 = byte & 3, c1 = (byte >> 2) & 3;
    if (c0 == 3 || c1 == 3 || c0 == c1) return false;
    const int cols[3] = {c0, c1, 3 - c0 - c1};
    m = {};
    for (int r = 0; r < 3; ++r) m[r][cols[r]] = (byte >> (4 + r)) & 1 ? -1 : 1;
    return true;
}
V3 mul(const Matrix& m, const V3& v) {
    V3 o{};
    for (int r = 0; r < 3; ++r) o[r] = m[r][0] * v[0] + m[r][1] * v[1] + m[r][2] * v[2];
    return o;
}
Matrix mul(const Matrix& a, const Matrix& b) {
    Matrix o{};
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
            for (int k = 0; k < 3; ++k) o[r][c] += a[r][k] * b[k][c];
    return o;
}
int det(const Matrix& m) {
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
           m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}
const Matrix kIdentity{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};

// Expected solid cells (vox axes) -> colour index.
using Cells = std::map<V3, int>;

// A model's voxels placed by matrix m and translation t with the pivot floor(size / 2).
void place(Cells& cells, const std::vector<vw::Voxel4>& voxels, V3 size, const Matrix& m, V3 t) {
    for (const vw::Voxel4& v : voxels) {
        const V3 local{v[0] - size[0] / 2, v[1] - size[1] / 2, v[2] - size[2] / 2};
        const V3 r = mul(m, local);
        cells[{r[0] + t[0], r[1] + t[1], r[2] + t[2]}] = v[3];
    }
}

// The world holds exactly `cells`, each at luxel (x, z, y) - origin, with its palette colour.
void expectCells(const VoxImport& import, const Cells& cells) {
    EXPECT_EQ(import.world.solidCount(), cells.size());
    const auto& o = import.voxOrigin;
    for (const auto& [c, index] : cells) {
        const int x = int(c[0] - o[0]), y = int(c[2] - o[2]), z = int(c[1] - o[1]);
        ASSERT_TRUE(import.world.solid(x, y, z))
            << "vox cell (" << c[0] << ", " << c[1] << ", " << c[2] << ")";
        EXPECT_EQ(import.world.get(x, y, z), defaultVoxPalette()[index]);
    }
}

const std::vector<vw::Voxel4> kAsymmetric = {{0, 0, 0, 1}, {2, 0, 0, 2}, {0, 3, 0, 3},
                                             {0, 0, 4, 4}, {1, 2, 3, 5}, {2, 3, 4, 6}};
const V3 kAsymmetricSize{3, 4, 5};

std::string translation(V3 t) {
    return std::to_string(t[0]) + " " + std::to_string(t[1]) + " " + std::to_string(t[2]);
}

TEST(VoxSceneGraph, TranslationsAndEveryPackedRotation) {
    int proper = 0, tested = 0;
    for (int byte = 0; byte < 128; ++byte) {
        Matrix m;
        if (!matrixOf(byte, m)) continue;
        ++tested;
        proper += det(m) == 1;
        const V3 t0{7, -3, 11}, t1{-20, 4, 2};
        const vw::Bytes bytes = vw::file(
            vw::cat({vw::model(3, 4, 5, kAsymmetric), vw::model(2, 2, 2, {{1, 1, 1, 9}}),
                     vw::transform(0, 1), vw::group(1, {2, 4}),
                     vw::transform(2, 3, {{{"_r", std::to_string(byte)}, {"_t", translation(t0)}}}),
                     vw::shape(3, {{0, -1}}), vw::transform(4, 5, {{{"_t", translation(t1)}}}),
                     vw::shape(5, {{1, -1}})}));
        Result<VoxImport> r = readVox(bytes, "rot.vox", {4});
        ASSERT_TRUE(r.ok()) << byte << ": " << r.error().message();
        Cells cells;
        place(cells, kAsymmetric, kAsymmetricSize, m, t0);
        place(cells, {{1, 1, 1, 9}}, {2, 2, 2}, kIdentity, t1);
        SCOPED_TRACE("rotation byte " + std::to_string(byte));
        expectCells(*r, cells);
        // The world starts at the lowest placed model corner (both models' boxes).
        V3 lo{INT64_MAX, INT64_MAX, INT64_MAX};
        for (int corner = 0; corner < 8; ++corner) {
            const V3 v{corner & 1 ? 2 : 0, corner & 2 ? 3 : 0, corner & 4 ? 4 : 0};
            const V3 c = mul(m, V3{v[0] - 1, v[1] - 2, v[2] - 2});
            for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], c[a] + t0[a]);
        }
        for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], t1[a] - 1);
        EXPECT_EQ(r->voxOrigin, lo);
        EXPECT_TRUE(r->warnings.empty()) << r->warnings.front();
    }
    EXPECT_EQ(tested, 48);  // 24 rotations and their mirror images
    EXPECT_EQ(proper, 24);
}

TEST(VoxSceneGraph, InstancingPlacesOneModelThreeTimes) {
    const std::vector<vw::Voxel4> voxels = {{0, 0, 0, 1}, {1, 0, 0, 2}, {0, 0, 1, 3}};
    const vw::Bytes bytes = vw::file(
        vw::cat({vw::model(2, 1, 2, voxels), vw::transform(0, 1), vw::group(1, {2, 4, 6}),
                 vw::transform(2, 3, {{{"_t", "0 0 0"}}}), vw::shape(3, {{0, -1}}),
                 vw::transform(4, 5, {{{"_t", "10 0 0"}}}), vw::shape(5, {{0, -1}}),
                 vw::transform(6, 7, {{{"_t", "0 6 3"}, {"_r", "17"}}}), vw::shape(7, {{0, -1}})}));
    Result<VoxImport> r = readVox(bytes, "inst.vox", {4});
    ASSERT_TRUE(r.ok()) << r.error().message();
    EXPECT_EQ(r->modelCount, 1);
    EXPECT_EQ(r->placedCount, 3);
    Cells cells;
    Matrix m17;
    ASSERT_TRUE(matrixOf(17, m17));
    place(cells, voxels, {2, 1, 2}, kIdentity, {0, 0, 0});
    place(cells, voxels, {2, 1, 2}, kIdentity, {10, 0, 0});
    place(cells, voxels, {2, 1, 2}, m17, {0, 6, 3});
    expectCells(*r, cells);
}

TEST(VoxSceneGraph, NestedGroupsComposeTransforms) {
    // root (t 10 0 0) -> group -> transform (r 24, t 0 5 0) -> group -> transform (r 40, t 1 0 2)
    // -> shape: world = R24 (R40 x + t2) + t1 + t0.
    const std::vector<vw::Voxel4> voxels = kAsymmetric;
    const vw::Bytes bytes = vw::file(vw::cat(
        {vw::model(3, 4, 5, voxels), vw::transform(0, 1, {{{"_t", "10 0 0"}}}), vw::group(1, {2}),
         vw::transform(2, 3, {{{"_r", "24"}, {"_t", "0 5 0"}}}), vw::group(3, {4}),
         vw::transform(4, 5, {{{"_r", "40"}, {"_t", "1 0 2"}}}), vw::shape(5, {{0, -1}})}));
    Result<VoxImport> r = readVox(bytes, "nest.vox", {4});
    ASSERT_TRUE(r.ok()) << r.error().message();
    Matrix a, b;
    ASSERT_TRUE(matrixOf(24, a));
    ASSERT_TRUE(matrixOf(40, b));
    const V3 inner = mul(a, V3{1, 0, 2});
    Cells cells;
    place(cells, voxels, kAsymmetricSize, mul(a, b),
          {inner[0] + 0 + 10, inner[1] + 5 + 0, inner[2] + 0 + 0});
    expectCells(*r, cells);
}

TEST(VoxSceneGraph, HiddenNodesAndHiddenLayersAreLeftOut) {
    const vw::Bytes bytes = vw::file(
        vw::cat({vw::model(1, 1, 1, {{0, 0, 0, 1}}), vw::model(1, 1, 1, {{0, 0, 0, 2}}),
                 vw::model(1, 1, 1, {{0, 0, 0, 3}}), vw::transform(0, 1), vw::group(1, {2, 4, 6}),
                 vw::transform(2, 3, {{{"_t", "0 0 0"}}}), vw::shape(3, {{0, -1}}),
                 vw::transform(4, 5, {{{"_t", "50 0 0"}}}, -1, {{"_hidden", "1"}}),
                 vw::shape(5, {{1, -1}}), vw::transform(6, 7, {{{"_t", "0 0 60"}}}, 1),
                 vw::shape(7, {{2, -1}}), vw::layer(0, false), vw::layer(1, true)}));
    Result<VoxImport> r = readVox(bytes, "hidden.vox", {4});
    ASSERT_TRUE(r.ok()) << r.error().message();
    EXPECT_EQ(r->placedCount, 1);
    EXPECT_EQ(r->world.size(), (Int3{1, 1, 1}));  // bounds from the visible model only
    EXPECT_EQ(r->world.get(0, 0, 0), defaultVoxPalette()[1]);
}

TEST(VoxSceneGraph, AnimationFramesPickKeyframes) {
    // Transform keyframes at frames 0 and 5; shape shows model 0 from frame 0, model 1 from 3.
    const vw::Bytes bytes = vw::file(vw::cat(
        {vw::model(1, 1, 1, {{0, 0, 0, 1}}), vw::model(1, 1, 1, {{0, 0, 0, 2}}),
         vw::model(3, 3, 3, {{2, 2, 2, 3}}), vw::transform(0, 1), vw::group(1, {2, 4}),
         vw::transform(2, 3, {{{"_f", "0"}, {"_t", "0 0 0"}}, {{"_f", "5"}, {"_t", "10 0 0"}}}),
         vw::shape(3, {{0, 0}, {1, 3}}), vw::transform(4, 5, {{{"_t", "-20 0 0"}}}),
         vw::shape(5, {{2, -1}})}));
    const auto at = [&](int frame) {
        Result<VoxImport> r = readVox(bytes, "anim.vox", {4, frame});
        EXPECT_TRUE(r.ok()) << r.error().message();
        return std::move(r).value();
    };
    const VoxImport f0 = at(0), f1 = at(1), f3 = at(3), f6 = at(6);
    EXPECT_EQ(f0.frameCount, 6);
    // The animated voxel sits 20 right of the fixed model's pivot at frames 0..4, 30 from 5.
    const auto animated = [](const VoxImport& i) {
        for (int x = 0; x < i.world.size().x; ++x) {
            if (i.world.solid(x, 1, 1) && i.world.get(x, 1, 1).b != defaultVoxPalette()[3].b) {
                return std::make_pair(int(x + i.voxOrigin[0]), int(i.world.get(x, 1, 1).b));
            }
        }
        return std::make_pair(-999, 0);
    };
    EXPECT_EQ(animated(f0), std::make_pair(0, int(defaultVoxPalette()[1].b)));
    EXPECT_EQ(animated(f1), std::make_pair(0, int(defaultVoxPalette()[1].b)));
    EXPECT_EQ(animated(f3), std::make_pair(0, int(defaultVoxPalette()[2].b)));
    EXPECT_EQ(animated(f6), std::make_pair(10, int(defaultVoxPalette()[2].b)));
    EXPECT_EQ(f0.world.solidCount(), 2u);  // frames are not laid side by side
    EXPECT_TRUE(f0.warnings.empty());
    // Past the last keyframe: the last keyframes hold, with a warning.
    const VoxImport f9 = at(9);
    EXPECT_EQ(animated(f9).first, 10);
    ASSERT_EQ(f9.warnings.size(), 1u);
    EXPECT_NE(f9.warnings[0].find("anim.vox: frame 9 is past the last keyframe (5)"),
              std::string::npos);
}

TEST(VoxSceneGraph, WithoutAGraphOneModelAtTheOriginSeveralSideBySide) {
    Result<VoxImport> one =
        readVox(vw::file(vw::model(2, 3, 4, {{1, 2, 3, 1}}), 150), "one.vox", {4});
    ASSERT_TRUE(one.ok()) << one.error().message();
    EXPECT_EQ(one->world.size(), (Int3{2, 4, 3}));
    EXPECT_TRUE(one->world.solid(1, 3, 2));
    EXPECT_TRUE(one->warnings.empty());
    Result<VoxImport> two = readVox(
        vw::file(vw::cat({vw::model(2, 2, 2, {{1, 0, 0, 1}}), vw::model(3, 5, 4, {{0, 4, 3, 2}})}),
                 150),
        "two.vox", {4});
    ASSERT_TRUE(two.ok()) << two.error().message();
    EXPECT_EQ(two->world.size(), (Int3{5, 4, 5}));
    EXPECT_TRUE(two->world.solid(2, 3, 4));
    ASSERT_EQ(two->warnings.size(), 1u);
    EXPECT_EQ(two->warnings[0],
              "two.vox: 2 models and no scene graph (nTRN/nGRP/nSHP): laid side by side along x");
}

}  // namespace
}  // namespace luxel::voxel
