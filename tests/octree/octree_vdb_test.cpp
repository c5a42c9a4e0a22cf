// OpenVDB import and export (octree_vdb.h): grids made with OpenVDB itself (a fog sphere, a sparse
// grid with active tiles, a level-set sphere) import voxel by voxel as the documented quantised
// opacity; octree -> vdb -> octree gives back the same tree; bad files give errors naming them.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>

#include <unistd.h>

#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>
#include <openvdb/tools/LevelSetSphere.h>
#include <openvdb/tools/LevelSetUtil.h>

#include "luxel/octree/octree_build.h"
#include "luxel/octree/octree_vdb.h"
#include "octree_vdb/vdb_source.h"
#include "support/temp_dir.h"

namespace luxel::octree {
namespace {

namespace fs = std::filesystem;
using openvdb::Coord;
using openvdb::CoordBBox;
using openvdb::FloatGrid;

std::string writeGrids(const test::TempDir& tmp, const std::string& name,
                       const openvdb::GridPtrVec& grids) {
    openvdb::initialize();
    const std::string path = tmp.path(name);
    openvdb::io::File(path).write(grids);
    return path;
}

// The documented mapping, written out independently of the importer.
std::uint8_t fogOpacity(float v, float max) {
    if (!(v > 0)) return 0;
    return static_cast<std::uint8_t>(std::lround(255.0 * std::min<double>(v, max) / max));
}

// Every cell of the imported tree against `expected(value of the grid voxel)`; the tree's
// content box is the grid's active box. Returns how many cells are neither 0 nor 255.
template <typename Expected>
int expectVoxelByVoxel(const Octree& tree, const FloatGrid& grid, Expected expected) {
    const CoordBBox box = grid.evalActiveVoxelBoundingBox();
    const Coord dim = box.dim();
    EXPECT_EQ(tree.size, Int3(dim.x(), dim.y(), dim.z()));
    auto accessor = grid.getConstAccessor();
    int partial = 0, mismatches = 0;
    for (int z = 0; z < dim.z(); ++z) {
        for (int y = 0; y < dim.y(); ++y) {
            for (int x = 0; x < dim.x(); ++x) {
                const std::uint8_t want = expected(accessor.getValue(box.min().offsetBy(x, y, z)));
                const std::uint8_t got = opacityAt(tree, {x, y, z});
                if (got != want && ++mismatches <= 5) {
                    ADD_FAILURE() << "cell " << x << " " << y << " " << z << ": " << int(got)
                                  << " != " << int(want);
                }
                partial += want > 0 && want < 255;
            }
        }
    }
    EXPECT_EQ(mismatches, 0);
    return partial;
}

FloatGrid::Ptr fogSphere() {
    // Centre off the voxel grid and below the origin: the active box starts at negative,
    // unaligned coordinates.
    auto sphere =
        openvdb::tools::createLevelSetSphere<FloatGrid>(11.0f, {-3.3f, 2.6f, -17.1f}, 1.0f, 3.0f);
    openvdb::tools::sdfToFogVolume(*sphere);  // interior 1 (active tiles), a ramp at the rim
    sphere->setName("fog");
    return sphere;
}

TEST(OctreeVdb, FogSphereImportsVoxelByVoxel) {
    const test::TempDir tmp;
    const auto fog = fogSphere();
    ASSERT_EQ(fog->getGridClass(), openvdb::GRID_FOG_VOLUME);
    auto vector = openvdb::Vec3SGrid::create();
    vector->setName("velocity");
    vector->tree().setValueOn(Coord(1, 2, 3), openvdb::Vec3s(1, 0, 0));
    // A vec3s grid first: the default is the first float grid, not the first grid.
    const std::string path = writeGrids(tmp, "fog.vdb", {vector, fog});
    auto tree = importVdb(path);
    ASSERT_TRUE(tree.ok()) << tree.error().message();
    EXPECT_FALSE(tree->hasColours());
    const int partial = expectVoxelByVoxel(*tree, *fog, [](float v) { return fogOpacity(v, 1); });
    EXPECT_GT(partial, 100) << "the ramp at the rim quantises to partial opacities";

    // `max` rescales: half the fog value reaches 255.
    tree = importVdb(path, {.grid = "fog", .max = 0.5f});
    ASSERT_TRUE(tree.ok()) << tree.error().message();
    expectVoxelByVoxel(*tree, *fog, [](float v) { return fogOpacity(v, 0.5f); });
}

TEST(OctreeVdb, SparseGridWithActiveTilesImportsWithoutVisitingThem) {
    const test::TempDir tmp;
    auto grid = FloatGrid::create(0.0f);
    grid->setName("sparse");
    auto& t = grid->tree();
    t.addTile(2, Coord(0, 0, 0), 0.25f, true);     // a 128^3 tile
    t.addTile(1, Coord(128, 8, 16), 0.75f, true);  // an 8^3 tile
    t.setValueOn(Coord(135, 100, 3), 1.0f);
    t.setValueOn(Coord(-5, 127, 40), 0.6f);  // unaligned lowest corner
    t.setValueOn(Coord(64, 64, 64), 0.8f);   // a leaf inside the big tile
    const std::string path = writeGrids(tmp, "sparse.vdb", {grid});
    auto tree = importVdb(path, {.grid = "sparse"});
    ASSERT_TRUE(tree.ok()) << tree.error().message();
    EXPECT_EQ(tree->size, Int3(141, 128, 128));
    expectVoxelByVoxel(*tree, *grid, [](float v) { return fogOpacity(v, 1); });
    EXPECT_EQ(opacityAt(*tree, {5 + 64, 64, 64}), 204);
    EXPECT_EQ(opacityAt(*tree, {5, 0, 0}), 64);

    // A tile far larger than any dense grid: built in one leaf per uniform cube.
    auto huge = FloatGrid::create(0.0f);
    huge->tree().addTile(3, Coord(0, 0, 0), 1.0f, true);  // a 4096^3 root tile
    huge->tree().setValueOn(Coord(5000, 17, 3), 0.5f);
    tree = importVdb(writeGrids(tmp, "huge.vdb", {huge}));
    ASSERT_TRUE(tree.ok()) << tree.error().message();
    EXPECT_EQ(tree->depth, 13);
    EXPECT_EQ(tree->size, Int3(5001, 4096, 4096));
    EXPECT_EQ(opacityAt(*tree, {4095, 4095, 4095}), 255);
    EXPECT_EQ(opacityAt(*tree, {4096, 17, 3}), 0);
    EXPECT_EQ(opacityAt(*tree, {5000, 17, 3}), 128);
    EXPECT_LT(measure(*tree).reachable, 200u);
}

// VdbSource::uniformBlock against reading every voxel: exact (never a wrong value, and uniform
// cubes are recognised) on cubes crossing tiles, leaves and the content box's edge.
TEST(OctreeVdb, UniformBlocksMatchTheVoxels) {
    auto grid = FloatGrid::create(0.0f);
    auto& t = grid->tree();
    t.addTile(1, Coord(8, 8, 8), 0.5f, true);
    t.addTile(1, Coord(16, 8, 8), 0.5f, true);
    t.fill(CoordBBox(Coord(3, 3, 3), Coord(30, 12, 9)), 0.5f, true);
    t.setValueOn(Coord(20, 20, 20), 1.0f);
    // Content that runs past the content box (cells 33.. and 27.. up to 43, beyond 40x36x30).
    t.fill(CoordBBox(Coord(30, 26, 18), Coord(40, 40, 40)), 1.0f, true);
    const Coord origin(-3, -1, -2);
    const Int3 size(40, 36, 30);
    const VdbSource source(*grid, origin, size, VdbQuantiser{});
    std::mt19937 rng(7);
    int uniform = 0, recognised = 0;
    for (int i = 0; i < 3000; ++i) {
        const int level = 2 + static_cast<int>(rng() % 3);
        const int side = 1 << level;
        const Int3 o(static_cast<int>(rng() % 48) & ~(side - 1),
                     static_cast<int>(rng() % 48) & ~(side - 1),
                     static_cast<int>(rng() % 48) & ~(side - 1));
        std::optional<std::uint8_t> truth;
        bool same = true;
        for (int z = 0; z < side; ++z)
            for (int y = 0; y < side; ++y)
                for (int x = 0; x < side; ++x) {
                    const Int3 c(o.x + x, o.y + y, o.z + z);
                    std::uint8_t v = 0;
                    if (c.x < size.x && c.y < size.y && c.z < size.z) {
                        Colour colour;
                        source.voxel(c, v, colour);
                    }
                    if (!truth) truth = v;
                    same = same && v == *truth;
                }
        const auto answer = source.uniformBlock(o, level);
        uniform += same;
        if (answer) {
            ASSERT_TRUE(same) << "cube " << o.x << " " << o.y << " " << o.z << " level " << level;
            ASSERT_EQ(answer->opacity, *truth);
        }
        // Uniform cubes are recognised unless they hang over the content box with content.
        const bool inside = o.x + side <= size.x && o.y + side <= size.y && o.z + side <= size.z;
        if (same && (inside || *truth == 0)) {
            EXPECT_TRUE(answer.has_value());
            recognised += answer.has_value();
        }
    }
    EXPECT_GT(uniform, 300);
    EXPECT_GT(recognised, 300);
}

TEST(OctreeVdb, LevelSetInteriorIsOpaque) {
    const test::TempDir tmp;
    auto sphere =
        openvdb::tools::createLevelSetSphere<FloatGrid>(12.0f, {0.5f, 0.0f, 0.0f}, 1.0f, 3.0f);
    sphere->setName("surface");
    auto tree = importVdb(writeGrids(tmp, "levelset.vdb", {sphere}));
    ASSERT_TRUE(tree.ok()) << tree.error().message();
    expectVoxelByVoxel(*tree, *sphere, [](float v) -> std::uint8_t { return v < 0 ? 255 : 0; });
    // The interior is inactive tiles and voxels: opaque all the same. Voxel centres within
    // r = 12 number about 4/3 pi r^3 = 7238.
    const OctreeStats stats = measure(*tree);
    EXPECT_NEAR(static_cast<double>(stats.solidVoxels), 7238.0, 7238.0 * 0.03);
}

TEST(OctreeVdb, RoundTripIsExact) {
    const test::TempDir tmp;
    // Every opacity 0..255, an empty border inside the content box, and uniform 8^3 cubes.
    Volume volume = *Volume::create({37, 20, 9}, false);
    for (int z = 0; z < 9; ++z)
        for (int y = 0; y < 18; ++y)
            for (int x = 0; x < 33; ++x) {
                const int v = x < 16 ? 200 : (x * 7 + y * 31 + z * 131) % 256;
                volume.set(x, y, z, static_cast<std::uint8_t>(v), Colour{});
            }
    const Octree tree = *buildOctree(volume, {.colours = false});
    const std::string path = tmp.path("round.vdb");
    ASSERT_TRUE(exportVdb(tree, path).ok());
    EXPECT_FALSE(fs::exists(path + ".tmp-" + std::to_string(::getpid())));

    // The file holds a pruned FOG_VOLUME "density" of opacity / 255, in index space.
    openvdb::io::File file(path);
    file.open();
    auto grid = openvdb::gridPtrCast<FloatGrid>(file.readGrid("density"));
    file.close();
    ASSERT_TRUE(grid);
    EXPECT_EQ(grid->getGridClass(), openvdb::GRID_FOG_VOLUME);
    EXPECT_FLOAT_EQ(grid->tree().getValue(Coord(3, 5, 4)), 200.0f / 255.0f);
    EXPECT_EQ(grid->tree().getValue(Coord(35, 5, 4)), 0.0f);
    EXPECT_GT(grid->tree().activeTileCount(), 0u) << "uniform 8^3 cubes are tiles";

    auto back = importVdb(path);
    ASSERT_TRUE(back.ok()) << back.error().message();
    EXPECT_EQ(back->depth, tree.depth);
    EXPECT_EQ(back->size, tree.size);
    EXPECT_EQ(back->nodes, tree.nodes) << "the same voxels build the same array";

    // Overwrites the target in place.
    ASSERT_TRUE(exportVdb(*back, path, {.grid = "opacity"}).ok());
    EXPECT_TRUE(importVdb(path, {.grid = "opacity"}).ok());
}

void expectError(const Result<Octree>& r, const std::string& path, const std::string& needle) {
    ASSERT_FALSE(r.ok()) << needle;
    EXPECT_EQ(r.error().message().rfind(path + ": ", 0), 0u) << r.error().message();
    EXPECT_NE(r.error().message().find(needle), std::string::npos) << r.error().message();
}

TEST(OctreeVdb, BadInputIsAnErrorNamingTheFile) {
    const test::TempDir tmp;
    const std::string missing = tmp.path("nowhere.vdb");
    expectError(importVdb(missing), missing, "cannot read OpenVDB file");

    const std::string junk = tmp.path("junk.vdb");
    {
        std::mt19937 rng(3);
        std::ofstream out(junk, std::ios::binary);
        for (int i = 0; i < 4096; ++i) out.put(static_cast<char>(rng()));
    }
    expectError(importVdb(junk), junk, "cannot read OpenVDB file");

    auto ints = openvdb::Int32Grid::create(0);
    ints->setName("labels");
    ints->tree().setValueOn(Coord(0, 0, 0), 3);
    const std::string noFloat = writeGrids(tmp, "ints.vdb", {ints});
    expectError(importVdb(noFloat), noFloat, "no float grid (the file holds labels (int32))");
    expectError(importVdb(noFloat, {.grid = "labels"}), noFloat, "holds int32 values");

    const std::string fog = writeGrids(tmp, "fog_named.vdb", {fogSphere()});
    expectError(importVdb(fog, {.grid = "density"}), fog, "no grid named 'density'");
    expectError(importVdb(fog, {.grid = "", .max = -1}), fog, "max must be a positive number");

    auto wide = FloatGrid::create(0.0f);
    wide->tree().setValueOn(Coord(-10, 0, 0), 1.0f);
    wide->tree().setValueOn(Coord(70000, 0, 0), 1.0f);
    const std::string widePath = writeGrids(tmp, "wide.vdb", {wide});
    expectError(importVdb(widePath), widePath, "spans 70011 voxels along x");

    auto empty = FloatGrid::create(0.0f);
    const std::string emptyPath = writeGrids(tmp, "empty.vdb", {empty});
    expectError(importVdb(emptyPath), emptyPath, "has no active voxels");

    Octree tree;
    tree.nodes.assign(8, 0);
    const Status unnamed = exportVdb(tree, tmp.path("x.vdb"), {.grid = ""});
    ASSERT_FALSE(unnamed.ok());
    EXPECT_NE(unnamed.error().message().find("grid name must not be empty"), std::string::npos);
    tree.nodes[3] = 300;  // a branch past the end
    const Status invalid = exportVdb(tree, tmp.path("x.vdb"));
    ASSERT_FALSE(invalid.ok());
    EXPECT_EQ(invalid.error().message().rfind(tmp.path("x.vdb") + ": ", 0), 0u);
    EXPECT_FALSE(fs::exists(tmp.path("x.vdb")));
}

}  // namespace
}  // namespace luxel::octree
