// `luxel` with OpenVDB files: `octree convert` .vdb -> .lxo -> .vdb keeps every voxel, a scene
// with "source": "vdb" renders, and bad grids are refused in one line.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>
#include <openvdb/tools/LevelSetSphere.h>
#include <openvdb/tools/LevelSetUtil.h>

#include "luxel/core/image_io.h"
#include "luxel/octree/octree_file.h"
#include "luxel/octree/octree_vdb.h"
#include "support/cli_fixture.h"

namespace {

namespace fs = std::filesystem;

using luxel::test::runLuxel;
using luxel::test::RunResult;

class CliOctreeVdb : public luxel::test::CliFixture {
  protected:
    // A fog sphere of radius 10 named "smoke" (1 inside, a ramp at the rim), 19 voxels across (its
    // active box).
    std::string writeFogSphere(const std::string& name) {
        openvdb::initialize();
        auto fog = openvdb::tools::createLevelSetSphere<openvdb::FloatGrid>(
            10.0f, openvdb::Vec3f(0, 0, 0), 1.0f, 3.0f);
        openvdb::tools::sdfToFogVolume(*fog);
        fog->setName("smoke");
        openvdb::io::File(path(name)).write(openvdb::GridPtrVec{fog});
        return path(name);
    }
};

TEST_F(CliOctreeVdb, ConvertsVdbToLxoAndBack) {
    const std::string vdb = writeFogSphere("sphere.vdb");
    RunResult r = runLuxel("octree convert " + vdb + " " + path("sphere.lxo"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("wrote " + path("sphere.lxo")), std::string::npos) << r.output;
    auto lxo = luxel::octree::readOctreeFile(path("sphere.lxo"));
    ASSERT_TRUE(lxo.ok()) << lxo.error().message();
    auto direct = luxel::octree::importVdb(vdb);
    ASSERT_TRUE(direct.ok()) << direct.error().message();
    EXPECT_EQ(lxo->size, direct->size);
    const luxel::Int3 size = lxo->size;
    EXPECT_EQ(luxel::octree::opacityAt(*lxo, {size.x / 2, size.y / 2, size.z / 2}), 255);

    r = runLuxel("octree convert " + path("sphere.lxo") + " " + path("back.vdb"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    auto back = luxel::octree::importVdb(path("back.vdb"));
    ASSERT_TRUE(back.ok()) << back.error().message();
    ASSERT_EQ(back->size, size);
    for (int z = 0; z < size.z; ++z)
        for (int y = 0; y < size.y; ++y)
            for (int x = 0; x < size.x; ++x) {
                ASSERT_EQ(luxel::octree::opacityAt(*back, {x, y, z}),
                          luxel::octree::opacityAt(*direct, {x, y, z}))
                    << x << " " << y << " " << z;
            }

    // --max 0.5: the rim's half-dense fog is opaque too, so more voxels are.
    r = runLuxel("octree convert " + vdb + " " + path("dense.lxo") + " --grid smoke --max 0.5");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    auto dense = luxel::octree::readOctreeFile(path("dense.lxo"));
    ASSERT_TRUE(dense.ok()) << dense.error().message();
    std::uint64_t opaque = 0, denseOpaque = 0;
    for (int z = 0; z < size.z; ++z)
        for (int y = 0; y < size.y; ++y)
            for (int x = 0; x < size.x; ++x) {
                opaque += luxel::octree::opacityAt(*lxo, {x, y, z}) == 255;
                denseOpaque += luxel::octree::opacityAt(*dense, {x, y, z}) == 255;
            }
    EXPECT_GT(denseOpaque, opaque);

    expectError("octree convert " + vdb + " " + path("x.lxo") + " --grid nothing",
                "no grid named 'nothing' (the file holds smoke (float))");
    expectError("octree convert " + path("sphere.lxo") + " " + path("x.lxo") + " --max 2",
                "--grid and --max apply to .vdb input");
    expectError("octree convert " + vdb + " " + path("x.raw"), "must end in .lxo or .vdb");
    write("junk.vdb", "not an OpenVDB file at all");
    expectError("octree convert " + path("junk.vdb") + " " + path("y.lxo"), "junk.vdb");
    EXPECT_FALSE(fs::exists(path("x.lxo")));
    EXPECT_FALSE(fs::exists(path("y.lxo")));
}

TEST_F(CliOctreeVdb, VdbSceneRenders) {
    writeFogSphere("sphere.vdb");
    const std::string scene = write("vdb.json", R"({
  "type": "octree",
  "octree": {"source": "vdb", "path": "sphere.vdb", "grid": "smoke", "max": 1},
  "camera": {"position": [9.5, 9.5, -40], "look_at": [9.5, 9.5, 9.5], "fov": 40,
             "size": [48, 48]},
  "render": {"mode": "volume", "opacity_scale": 0.3, "sky": [1, 1, 1]}
})");
    RunResult r = runLuxel("render " + scene + " --backend cpu --out " + path("vdb.png"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    auto image = luxel::readPng(path("vdb.png"));
    ASSERT_TRUE(image.ok()) << image.error().message();
    ASSERT_EQ(image->width(), 48);
    // The sphere is in the middle of the picture: the white sky behind shows at the corner only.
    EXPECT_LT(image->at(24, 24, 0), image->at(1, 1, 0));

    r = runLuxel("info " + scene);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("depth 5 (32^3)"), std::string::npos) << r.output;

    const std::string badGrid = write("bad.json", R"({"type": "octree",
  "octree": {"source": "vdb", "path": "sphere.vdb", "grid": "density"},
  "camera": {"position": [0, 0, -40], "yaw": 0, "pitch": 0, "fov": 40, "size": [8, 8]}})");
    expectError("info " + badGrid, "no grid named 'density'");
    expectError("info " + badGrid, "bad.json:2:");
    const std::string badMax = write("badmax.json", R"({"type": "octree",
  "octree": {"source": "vdb", "path": "sphere.vdb", "max": -1},
  "camera": {"position": [0, 0, -40], "yaw": 0, "pitch": 0, "fov": 40, "size": [8, 8]}})");
    expectError("info " + badMax, "octree.max");
}

}  // namespace
