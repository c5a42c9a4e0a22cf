// The voxel radiance cascades' memory limit counts the segments' runs through glass
// (docs/algorithms/voxel-radiance-cascades.md §5): the estimate made before building leaves
// them out, so they are counted as they are cast and the build is refused, with the bytes, when
// they would pass the limit; a limit with room for them builds, and so does the shipped glass
// scene under the default limit.
#include <gtest/gtest.h>

#include <string>

#include "luxel/core/memory.h"
#include "luxel/voxel/radiance_cascades.h"
#include "luxel/voxel/voxel_scene.h"
#include "voxel/plain_light_worlds.h"

namespace {

using namespace luxel;
using namespace luxel::voxel;
using namespace luxel::voxel::test;

constexpr Voxel kGlass{255, 255, 255, 1};  // texture slot 0

// A white floor under a glass slab three voxels thick across the whole world, and a sky: most
// segments above the floor cross the glass.
VoxelWorld floorUnderGlass() {
    VoxelWorld world = makeWorld({24, 10, 24});
    for (int z = 0; z < 24; ++z)
        for (int x = 0; x < 24; ++x) {
            world.set(x, 0, z, kWhite);
            for (int y = 3; y < 6; ++y) world.set(x, y, z, kGlass);
        }
    world.refreshEmptySpace();
    return world;
}

ShadeOptions glassLight() {
    ShadeOptions o = plainLight(0.5f, Rgb(0.0f), Rgb(1.0f));
    EXPECT_TRUE(o.materials.setSlot(0, glass(Rgb(0.05f))).ok());
    return o;
}

TEST(CascadesGlassMemory, RunsThroughGlassPastTheLimitAreRefusedWithTheirBytes) {
    const VoxelWorld world = floorUnderGlass();
    const ShadeOptions o = glassLight();
    const CascadeEstimate estimate = estimateCascades(world);
    ASSERT_TRUE(estimate.fits);
    // Room for the estimate and 1 KiB: about fifty passages.
    CascadeOptions tight;
    tight.spacing = estimate.spacing;
    tight.memoryLimit = estimate.bytes + 1024;
    auto refused = RadianceCascades::create(world, nullptr, o, tight);
    ASSERT_FALSE(refused.ok());
    const std::string message = refused.error().message();
    EXPECT_NE(message.find("runs through glass"), std::string::npos) << message;
    EXPECT_NE(message.find(formatBytes(estimate.bytes) + " estimated"), std::string::npos)
        << message;
    EXPECT_NE(message.find("limit of " + formatBytes(tight.memoryLimit)), std::string::npos)
        << message;

    // With room for the passages it builds, and they take more than the 1 KiB refused.
    CascadeOptions roomy = tight;
    roomy.memoryLimit = estimate.bytes + (std::uint64_t(64) << 20);
    auto built = RadianceCascades::create(world, nullptr, o, roomy);
    ASSERT_TRUE(built.ok()) << built.error().message();
    EXPECT_GT(built->stats().passages * 20, 1024);
    EXPECT_LE(built->stats().bytes, roomy.memoryLimit);
    built->solve();
    EXPECT_GT(built->indirectIrradiance({12, 0, 12}, {0, 1, 0}, {12.5, 1.0, 12.5}).g, 0.1f);

    // Without refraction nothing passes the glass: the tight limit builds.
    ShadeOptions plain = o;
    plain.refraction = false;
    auto opaque = RadianceCascades::create(world, nullptr, plain, tight);
    ASSERT_TRUE(opaque.ok()) << opaque.error().message();
    EXPECT_EQ(opaque->stats().passages, 0);
    // Turning the glass on refuses its cast, leaves cascades that still light and render without
    // crashing, and the next setLight casts again (and is refused again).
    EXPECT_FALSE(opaque->setLight(o).ok());
    opaque->solve();
    const Rgb e = opaque->indirectIrradiance({12, 0, 12}, {0, 1, 0}, {12.5, 1.0, 12.5});
    EXPECT_TRUE(e.g >= 0.0f) << e.g;
    const Status again = opaque->setLight(o);
    ASSERT_FALSE(again.ok());
    EXPECT_NE(again.error().message().find("runs through glass"), std::string::npos);
    // And back to no refraction, it casts whole again.
    EXPECT_TRUE(opaque->setLight(plain).ok());
}

TEST(CascadesGlassMemory, TheGlassSceneBuildsUnderTheDefaultLimit) {
    auto scene =
        loadVoxelScene(std::string(LUXEL_SOURCE_DIR) + "/scenes/voxel/glass.json", 160, 90);
    ASSERT_TRUE(scene.ok()) << scene.error().message();
    const CascadeEstimate estimate = estimateCascades(scene->world);
    auto cascades = RadianceCascades::create(scene->world, &scene->textures, scene->shading);
    ASSERT_TRUE(cascades.ok()) << cascades.error().message();
    const CascadeStats stats = cascades->stats();
    EXPECT_GT(stats.passages, 1'000'000);  // 1.69 M runs through its glass cube and sphere
    EXPECT_LE(stats.bytes, estimate.limit);
}

}  // namespace
