// The LeafOrder attribute layout (octree.h, docs/algorithms/sparse-voxel-octree.md §1 "Colour"):
// exact colours through the per-octant leaf counts, geometry shared as if uncoloured, edits,
// files, hostile input and the GPU passes against their CPU twins.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>

#include "luxel/core/metrics.h"
#include "luxel/gpu/context.h"
#include "luxel/octree/octree_build.h"
#include "luxel/octree/octree_edit.h"
#include "luxel/octree/octree_file.h"
#include "luxel/octree/octree_gpu.h"
#include "luxel/octree/octree_render.h"
#include "luxel/octree/octree_trace.h"
#include "luxel/octree/octree_validate.h"
#include "luxel/voxel/generators.h"
#include "support/gpu_test_context.h"
#include "support/temp_dir.h"

namespace luxel::octree {
namespace {

constexpr BuildOptions kLeafOrder{.layout = AttributeLayout::LeafOrder};
constexpr BuildOptions kPerEntry{.layout = AttributeLayout::PerEntry};

Colour jitter(std::mt19937& rng) {
    return Colour{static_cast<std::uint8_t>(100 + rng() % 40),
                  static_cast<std::uint8_t>(60 + rng() % 40), 40, 1};
}

// Ground with per-voxel colour jitter below a wavy height, a uniformly coloured box (collapses
// even in leaf order), translucent specks and an empty sky: every kind of leaf.
Volume jitteredVolume(Int3 size, std::uint32_t seed) {
    Volume v = *Volume::create(size, true);
    std::mt19937 rng(seed);
    for (int z = 0; z < size.z; ++z)
        for (int x = 0; x < size.x; ++x) {
            const int h = size.y / 3 + static_cast<int>(3 * std::sin(x * 0.3) * std::cos(z * 0.2));
            for (int y = 0; y < h; ++y) v.set(x, y, z, 255, jitter(rng));
        }
    for (int z = 8; z < 16; ++z)
        for (int y = 16; y < 24; ++y)
            for (int x = 16; x < 24; ++x) v.set(x, y, z, 255, Colour{0, 0, 200, 1});
    for (int i = 0; i < 200; ++i) {
        v.set(static_cast<int>(rng() % size.x), static_cast<int>(rng() % size.y),
              static_cast<int>(rng() % size.z), static_cast<std::uint8_t>(1 + rng() % 254),
              jitter(rng));
    }
    return v;
}

void expectSameVoxels(const Octree& tree, const Volume& v, const char* what) {
    const Int3 s = v.size();
    for (int z = 0; z < s.z; ++z)
        for (int y = 0; y < s.y; ++y)
            for (int x = 0; x < s.x; ++x) {
                ASSERT_EQ(opacityAt(tree, {x, y, z}), v.opacity(x, y, z)) << what;
                const Colour want = v.opacity(x, y, z) > 0 ? v.colour(x, y, z) : Colour{};
                ASSERT_EQ(colourAt(tree, {x, y, z}), want)
                    << what << " at " << x << "," << y << "," << z;
            }
}

TEST(OctreeLeafOrder, ColourAtIsTheSourceColourOfEveryVoxel) {
    const Volume v = jitteredVolume({40, 33, 29}, 1);
    auto tree = buildOctree(v, kLeafOrder);
    ASSERT_TRUE(tree.ok()) << tree.error().message();
    EXPECT_EQ(tree->attributes(), AttributeLayout::LeafOrder);
    ASSERT_TRUE(validateOctree(*tree).ok()) << validateOctree(*tree).error().message();
    EXPECT_EQ(tree->leafCounts.size(), tree->nodes.size() / 8);
    EXPECT_EQ(tree->leafCounts[0], tree->colours.size());
    expectSameVoxels(*tree, v, "leaf order");
}

TEST(OctreeLeafOrder, GeometryIsSharedAsIfUncoloured) {
    // Colours that follow the opacity: the array is the uncoloured build's, bit for bit.
    Volume banded = *Volume::create({48, 48, 48}, true);
    for (int z = 0; z < 48; ++z)
        for (int y = 0; y < 20; ++y)
            for (int x = 0; x < 48; ++x) {
                const auto o = static_cast<std::uint8_t>(y < 10 ? 255 : 90 + (x * z) % 3);
                banded.set(x, y, z, o, Colour{o, 7, 7, 1});
            }
    const Octree plain = *buildOctree(banded, {.colours = false});
    const Octree banding = *buildOctree(banded, kLeafOrder);
    EXPECT_EQ(banding.nodes, plain.nodes);
    // Per-voxel jitter: leaves of one opacity but many colours cannot collapse (colours are
    // exact), so each such cube adds one octant per level, shared by all cubes of that opacity;
    // everything else is the uncoloured array.
    const Volume v = jitteredVolume({64, 64, 64}, 2);
    const OctreeStats uncoloured = measure(*buildOctree(v, {.colours = false}));
    const OctreeStats leafOrder = measure(*buildOctree(v, kLeafOrder));
    const OctreeStats perEntry = measure(*buildOctree(v, kPerEntry));
    EXPECT_EQ(leafOrder.solidVoxels, uncoloured.solidVoxels);
    EXPECT_LE(leafOrder.octants, uncoloured.octants + 6 * 256);
    EXPECT_LT(leafOrder.octants * 4, perEntry.octants);
    EXPECT_EQ(leafOrder.attributeIndexBytes, leafOrder.octants * 4);
    EXPECT_EQ(perEntry.attributeIndexBytes, 0u);
}

// The 512^3 terrain claim (docs/algorithms/sparse-voxel-octree.md §2) at 128^3: the same
// voxel-world terrain (per-voxel colour jitter) in both layouts.
TEST(OctreeLeafOrder, JitteredTerrainGeometryIsFarBelowPerEntry) {
    voxel::VoxelWorld world = *voxel::VoxelWorld::create({128, 128, 128});
    voxel::TerrainOptions t;
    t.seed = 7;
    t.baseHeight = 0.35;
    t.amplitude = 0.28;
    t.frequency = 0.016;
    t.waterLevel = 0.3;
    ASSERT_TRUE(voxel::generateTerrain(world, t).ok());
    const OctreeStats perEntry = measure(*buildOctree(world, kPerEntry));
    const Octree tree = *buildOctree(world);  // voxel worlds default to leaf order
    ASSERT_EQ(tree.attributes(), AttributeLayout::LeafOrder);
    const OctreeStats leafOrder = measure(tree);
    const OctreeStats plain = measure(*buildOctree(world, {.colours = false}));
    std::printf(
        "128^3 terrain, bits per solid voxel: per-entry %.3f, leaf-order %.4f, "
        "uncoloured %.4f; leaf-order index %llu B, colours %llu B\n",
        perEntry.bitsPerSolidVoxel, leafOrder.bitsPerSolidVoxel, plain.bitsPerSolidVoxel,
        static_cast<unsigned long long>(leafOrder.attributeIndexBytes),
        static_cast<unsigned long long>(leafOrder.attributeBytes));
    // Measured: per-entry 37.2, leaf-order 0.540, uncoloured 0.527 bits per solid voxel.
    EXPECT_LT(leafOrder.bitsPerSolidVoxel, 0.6);
    EXPECT_LT(leafOrder.bitsPerSolidVoxel * 50, perEntry.bitsPerSolidVoxel);
    EXPECT_LT(leafOrder.geometryBytes, plain.geometryBytes * 105 / 100);
    EXPECT_EQ(leafOrder.solidVoxels, plain.solidVoxels);
}

TEST(OctreeLeafOrder, RandomEditsKeepColoursRight) {
    Volume v = jitteredVolume({32, 32, 32}, 3);
    OctreeEditor editor(*buildOctree(v, kLeafOrder));
    std::mt19937 rng(4);
    for (int i = 0; i < 600; ++i) {
        // Half the edits in the sky and the blue box, where leaves are wider than a voxel.
        const Int3 c(static_cast<int>(rng() % 32), static_cast<int>(rng() % 32),
                     static_cast<int>(rng() % 32));
        const auto o = static_cast<std::uint8_t>(rng() % 3 == 0 ? 0 : rng() % 256);
        // A quarter of the edits restore the blue of the box, so octants collapse again.
        const Colour col = rng() % 4 == 0 ? Colour{0, 0, 200, 1} : jitter(rng);
        const auto opacity = static_cast<std::uint8_t>(o == 0 ? 0 : (rng() % 4 == 0 ? 255 : o));
        ASSERT_TRUE(editor.set(c, opacity, col).ok());
        v.set(c.x, c.y, c.z, opacity, col);
        if (i % 100 == 0) {
            ASSERT_TRUE(validateOctree(editor.tree()).ok())
                << validateOctree(editor.tree()).error().message();
        }
    }
    ASSERT_TRUE(validateOctree(editor.tree()).ok())
        << validateOctree(editor.tree()).error().message();
    expectSameVoxels(editor.tree(), v, "after edits");
    editor.compact();
    ASSERT_TRUE(validateOctree(editor.tree()).ok())
        << validateOctree(editor.tree()).error().message();
    expectSameVoxels(editor.tree(), v, "after compaction");
    const Octree fresh = *buildOctree(v, kLeafOrder);
    EXPECT_EQ(editor.tree().nodes.size(), fresh.nodes.size());
    EXPECT_EQ(editor.tree().colours, fresh.colours);
}

TEST(OctreeLeafOrder, AnEditInsideAWideLeafSplicesItsColours) {
    Volume v = *Volume::create({64, 64, 64}, true);
    for (int z = 0; z < 64; ++z)
        for (int y = 0; y < 32; ++y)
            for (int x = 0; x < 64; ++x) v.set(x, y, z, 255, Colour{9, 9, 9, 1});
    OctreeEditor editor(*buildOctree(v, kLeafOrder));
    ASSERT_EQ(editor.tree().colours.size(), 8u);  // two halves of one colour, six of sky
    ASSERT_TRUE(editor.set({5, 6, 7}, 255, Colour{200, 0, 0, 1}).ok());
    EXPECT_EQ(editor.tree().colours.size(), 8u + 7 * 5);  // the root leaf split over 5 levels
    EXPECT_EQ(colourAt(editor.tree(), {5, 6, 7}), (Colour{200, 0, 0, 1}));
    EXPECT_EQ(colourAt(editor.tree(), {5, 6, 6}), (Colour{9, 9, 9, 1}));
    ASSERT_TRUE(editor.set({5, 6, 7}, 255, Colour{9, 9, 9, 1}).ok());  // undo collapses
    EXPECT_EQ(editor.tree().colours.size(), 8u);
    EXPECT_TRUE(validateOctree(editor.tree()).ok());
}

TEST(OctreeLeafOrder, FilesRoundTripAndVersionOneStillReads) {
    const Octree tree = *buildOctree(jitteredVolume({24, 20, 30}, 5), kLeafOrder);
    const test::TempDir tmp;
    const std::string path = tmp.path("leaf_order.lxo");
    ASSERT_TRUE(writeOctreeFile(path, tree).ok());
    auto back = readOctreeFile(path);
    ASSERT_TRUE(back.ok()) << back.error().message();
    EXPECT_EQ(back->attributes(), AttributeLayout::LeafOrder);
    EXPECT_EQ(back->nodes, tree.nodes);
    EXPECT_EQ(back->leafCounts, tree.leafCounts);
    EXPECT_EQ(back->colours, tree.colours);
    EXPECT_EQ(back->size, tree.size);
    // A version 1 file (40-byte header, flags, one colour per entry), written by hand.
    const Octree perEntry = *buildOctree(jitteredVolume({24, 20, 30}, 5), kPerEntry);
    std::string v1 = "LXOCTREE";
    auto put32 = [&](std::uint32_t x) {
        for (int i = 0; i < 4; ++i) v1.push_back(static_cast<char>((x >> (8 * i)) & 0xff));
    };
    for (std::uint32_t x : {1u, 5u, 24u, 20u, 30u, 1u}) put32(x);
    put32(static_cast<std::uint32_t>(perEntry.nodes.size()));
    put32(0);
    for (std::uint32_t e : perEntry.nodes) put32(e);
    for (const Colour& c : perEntry.colours) put32(c.r | c.g << 8 | c.b << 16 | c.a << 24);
    auto old = parseOctree(v1, "old.lxo");
    ASSERT_TRUE(old.ok()) << old.error().message();
    EXPECT_EQ(old->attributes(), AttributeLayout::PerEntry);
    EXPECT_EQ(old->nodes, perEntry.nodes);
    EXPECT_EQ(old->colours, perEntry.colours);
}

TEST(OctreeLeafOrder, HostileFilesAreRejectedWithTheReason) {
    const Octree tree = *buildOctree(jitteredVolume({24, 20, 30}, 6), kLeafOrder);
    const std::string good = serializeOctree(tree);
    auto expectError = [](const std::string& bytes, const std::string& needle) {
        auto parsed = parseOctree(bytes, "bad.lxo");
        ASSERT_FALSE(parsed.ok()) << needle;
        EXPECT_NE(parsed.error().message().find(needle), std::string::npos)
            << parsed.error().message();
    };
    const std::size_t countsAt = kOctreeHeaderBytes + 4 * tree.nodes.size();
    std::string b = good;
    b[countsAt + 4 * 1] ^= 1;  // octant 8's leaf count off by one
    expectError(b, "leaf count of octant 8 is");
    b = good;
    b[countsAt] ^= 2;  // the root's count
    expectError(b, "leaf count of octant 0 is");
    // Four colours short, the header agreeing with the bytes.
    b = good.substr(0, good.size() - 16);
    const std::uint64_t fewer = tree.colours.size() - 4;
    for (int i = 0; i < 8; ++i) b[40 + i] = static_cast<char>((fewer >> (8 * i)) & 0xff);
    expectError(b, "leaf-order colours for");
    // No colours at all.
    b = good.substr(0, countsAt + 4 * tree.leafCounts.size());
    for (int i = 0; i < 8; ++i) b[40 + i] = 0;
    expectError(b, "0 leaf-order colours for");
    expectError(good.substr(0, good.size() - 4), "bytes follow it");
    // Per-entry colours whose count is not the entry count.
    b = serializeOctree(*buildOctree(jitteredVolume({24, 20, 30}, 6), kPerEntry));
    b[40] ^= 8;
    expectError(b, "per-entry colours need one each");
    // In memory: the validator recomputes the counts.
    Octree broken = tree;
    broken.leafCounts.pop_back();
    EXPECT_FALSE(validateOctree(broken).ok());
    broken = tree;
    broken.colours.push_back(Colour{});
    EXPECT_FALSE(validateOctree(broken).ok());
}

TEST(OctreeLeafOrder, TracedHitsCarryTheirLeafOrderColour) {
    const Volume v = jitteredVolume({40, 33, 29}, 7);
    const Octree tree = *buildOctree(v, kLeafOrder);
    std::mt19937 rng(8);
    int hits = 0;
    for (int i = 0; i < 2000; ++i) {
        const voxel::Ray ray{{static_cast<double>(rng() % 400) / 10.0, 40.0,
                              static_cast<double>(rng() % 290) / 10.0},
                             {(static_cast<double>(rng() % 200) - 100) / 100.0, -1.0,
                              (static_cast<double>(rng() % 200) - 100) / 100.0}};
        const OctreeHit h = castRay(tree, ray);
        if (!h.hit.hit) continue;
        ++hits;
        ASSERT_EQ(tree.colours[h.colourIndex], colourAt(tree, h.hit.voxel));
        ASSERT_EQ(tree.colours[h.colourIndex],
                  v.colour(h.hit.voxel.x, h.hit.voxel.y, h.hit.voxel.z));
    }
    EXPECT_GT(hits, 600);
}

TEST(OctreeLeafOrder, GpuPassesMatchTheirCpuTwins) {
    if (!test::sharedGpuContext())
        GTEST_SKIP() << "no Vulkan device: " << gpu::Context::create().error().message();
    const Octree tree = *buildOctree(jitteredVolume({40, 33, 29}, 9), kLeafOrder);
    auto uploaded = OctreeGpu::create(*test::sharedGpuContext(), tree);
    ASSERT_TRUE(uploaded.ok()) << uploaded.error().message();
    // Rays: exact dyadic origins and directions, so the walks agree hit for hit.
    std::mt19937 rng(10);
    const double dyadic[] = {0.0, 0.25, -0.25, 0.5, -0.5, 1.0, -1.0};
    std::vector<voxel::Ray> rays;
    for (int i = 0; i < 2000; ++i) {
        rays.push_back({{static_cast<double>(rng() % 40) + 0.25 * (i % 4), 36.0,
                         static_cast<double>(rng() % 29) + 0.5},
                        {dyadic[rng() % 7], -1.0, dyadic[rng() % 7]}});
    }
    const std::vector<OctreeHit> cpu = castRays(tree, rays);
    auto gpuHits = uploaded->castRays(rays);
    ASSERT_TRUE(gpuHits.ok()) << gpuHits.error().message();
    int hits = 0;
    for (std::size_t i = 0; i < rays.size(); ++i) {
        ASSERT_EQ((*gpuHits)[i].hit.hit, cpu[i].hit.hit) << "ray " << i;
        if (!cpu[i].hit.hit) continue;
        ++hits;
        ASSERT_EQ((*gpuHits)[i].hit.voxel, cpu[i].hit.voxel) << "ray " << i;
        ASSERT_EQ((*gpuHits)[i].colourIndex, cpu[i].colourIndex) << "ray " << i;
    }
    EXPECT_GT(hits, 700);
    // Images: colours come from the leaf order on both backends, and differ from grey.
    const voxel::Camera camera = *voxel::Camera::lookAt({70, 50, -30}, {20, 12, 14}, 40, 48, 36);
    for (OctreeMode mode : {OctreeMode::Surface, OctreeMode::Volume}) {
        OctreeRenderOptions o;
        o.mode = mode;
        o.opacityScale = mode == OctreeMode::Volume ? 0.3f : 1.0f;
        auto c = renderOctree(tree, camera, o);
        auto g = uploaded->render(camera, o);
        ASSERT_TRUE(c.ok() && g.ok());
        EXPECT_LT(compareImages(*g, *c)->relativeL1, 1e-2) << octreeModeName(mode);
        Octree grey = tree;
        grey.colours.clear();
        grey.leafCounts.clear();
        EXPECT_GT(compareImages(*renderOctree(grey, camera, o), *c)->relativeL1, 0.05)
            << octreeModeName(mode);
    }
    EXPECT_EQ(test::sharedGpuContext()->validationMessages(), 0)
        << test::sharedGpuContext()->lastValidationMessage();
}

}  // namespace
}  // namespace luxel::octree
