// The voxel radiance cascades' memory limit counts the segments' runs through glass
// (docs/algorithms/voxel-radiance-cascades.md §5): the estimate made before building leaves
// them out, so they are counted as they are cast and the build is refused, with the bytes, when
// they would pass the limit; a limit with room for them builds, and so does the shipped glass
// scene under the default limit.
#include <gtest/gtest.h>

#include <algorithm>
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

// The bytes the estimate plans at a spacing given by the user and the runs through glass that
// spacing casts, built with room to spare.
struct SpacingNeeds {
    std::uint64_t planned = 0;
    std::int64_t passages = 0;
};

SpacingNeeds needsAt(const VoxelWorld& world, const ShadeOptions& o, int spacing) {
    CascadeOptions given;
    given.spacing = spacing;
    given.memoryLimit = std::uint64_t(1) << 30;
    SpacingNeeds needs;
    needs.planned = estimateCascades(world, given).bytes;
    auto built = RadianceCascades::create(world, nullptr, o, given);
    EXPECT_TRUE(built.ok()) << built.error().message();
    if (built.ok()) needs.passages = built->stats().passages;
    return needs;
}

// An automatic spacing whose runs through glass do not fit is doubled until they do, as the
// estimate doubles it, and the stats say which spacing was taken and why; a spacing the user
// gave is never changed: the build is refused.
TEST(CascadesGlassMemory, AnAutomaticSpacingDoublesWhereTheRunsThroughGlassDoNotFit) {
    const VoxelWorld world = floorUnderGlass();
    const ShadeOptions o = glassLight();
    const SpacingNeeds two = needsAt(world, o, 2), four = needsAt(world, o, 4);
    // Room for the estimate at spacing 2 and, beside spacing 4's, for its passages (their table
    // grows by doubling: its peak stays under 3 times their bytes), but not for spacing 2's.
    const std::uint64_t each = 20;
    const std::uint64_t limit = std::max(two.planned, four.planned + 4 * four.passages * each);
    ASSERT_GT(four.passages, 0);
    ASSERT_LT(limit - two.planned, two.passages * each) << "spacing 2 would fit";
    CascadeOptions automatic;
    automatic.memoryLimit = limit;
    ASSERT_EQ(estimateCascades(world, automatic).spacing, 2);

    auto doubled = RadianceCascades::create(world, nullptr, o, automatic);
    ASSERT_TRUE(doubled.ok()) << doubled.error().message();
    const CascadeStats stats = doubled->stats();
    EXPECT_EQ(stats.spacing, 4);
    EXPECT_EQ(stats.passages, four.passages);
    EXPECT_LE(stats.bytes, limit);
    const std::string& note = stats.spacingNote;
    EXPECT_NE(note.find("probe spacing 4, not 2"), std::string::npos) << note;
    EXPECT_NE(note.find("runs through glass"), std::string::npos) << note;
    EXPECT_NE(note.find(formatBytes(two.planned) + " estimated"), std::string::npos) << note;
    EXPECT_NE(note.find("limit of " + formatBytes(limit)), std::string::npos) << note;
    // The same light as spacing 4 given by the user.
    CascadeOptions givenFour = automatic;
    givenFour.spacing = 4;
    auto four4 = RadianceCascades::create(world, nullptr, o, givenFour);
    ASSERT_TRUE(four4.ok()) << four4.error().message();
    EXPECT_TRUE(four4->stats().spacingNote.empty());
    doubled->solve();
    four4->solve();
    const Rgb e = doubled->indirectIrradiance({12, 0, 12}, {0, 1, 0}, {12.5, 1.0, 12.5});
    EXPECT_GT(e.g, 0.1f);
    EXPECT_EQ(e.g, four4->indirectIrradiance({12, 0, 12}, {0, 1, 0}, {12.5, 1.0, 12.5}).g);

    // Spacing 2 given by the user under the same limit: refused, not changed.
    CascadeOptions givenTwo = automatic;
    givenTwo.spacing = 2;
    auto refused = RadianceCascades::create(world, nullptr, o, givenTwo);
    ASSERT_FALSE(refused.ok());
    const std::string message = refused.error().message();
    EXPECT_NE(message.find("runs through glass"), std::string::npos) << message;
    EXPECT_NE(message.find("try a larger --rc-spacing"), std::string::npos) << message;

    // With room for spacing 2's runs, the automatic spacing stays 2 and there is no note.
    CascadeOptions roomy;
    roomy.memoryLimit = two.planned + 4 * two.passages * each;
    auto kept = RadianceCascades::create(world, nullptr, o, roomy);
    ASSERT_TRUE(kept.ok()) << kept.error().message();
    EXPECT_EQ(kept->stats().spacing, 2);
    EXPECT_TRUE(kept->stats().spacingNote.empty()) << kept->stats().spacingNote;

    // Glass turned on by setLight under the limit doubles the spacing as create does, and
    // turned off again goes back to spacing 2.
    ShadeOptions plain = o;
    plain.refraction = false;
    auto later = RadianceCascades::create(world, nullptr, plain, automatic);
    ASSERT_TRUE(later.ok()) << later.error().message();
    EXPECT_EQ(later->stats().spacing, 2);
    ASSERT_TRUE(later->setLight(o).ok());
    EXPECT_EQ(later->stats().spacing, 4);
    EXPECT_EQ(later->stats().passages, four.passages);
    EXPECT_EQ(later->stats().spacingNote, note);
    ASSERT_TRUE(later->setLight(plain).ok());
    EXPECT_EQ(later->stats().spacing, 2);
    EXPECT_EQ(later->stats().passages, 0);
    EXPECT_TRUE(later->stats().spacingNote.empty());
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
