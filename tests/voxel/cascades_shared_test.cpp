// A lighting pass merges an entry whose weighted corners share one code from that code alone
// (src/voxel/cascades/cascade_shared.h; docs/algorithms/voxel-radiance-cascades.md §5): the faces'
// irradiance after several passes, and after new sun and sky, equals to the bit what merging
// every entry from its eight codes gives, on the cottage (chains through its windows) and on a
// floor under glass; and the stream holds shared codes of every kind and mixed entries.
#include <gtest/gtest.h>

#include <string>

#include "luxel/voxel/voxel_scene.h"
#include "voxel/cascade_states.h"
#include "voxel/cascades/cascade_shared.h"
#include "voxel/cascades/cascade_state.h"
#include "voxel/plain_light_worlds.h"

namespace {

using namespace luxel;
using namespace luxel::voxel;
using namespace luxel::voxel::cascades;
using namespace luxel::voxel::test;

// The pass as it was before the shared codes: every entry merged from its codes.
void clearShared(RadianceCascades::State& state) {
    state.faces.shared.clear();
    state.faces.mixed.clear();
    for (LevelData& level : state.levels) {
        level.shared.clear();
        level.mixed.clear();
        level.sharedStart.clear();
    }
}

// How many of the stream's entries share a code of each kind, over the faces and the levels.
struct Kinds {
    int mixed = 0, further = 0, sky = 0, face = 0, passage = 0;
    void add(std::uint32_t code) {
        mixed += code == kMixed;
        further += code == kContinue;
        sky += code == kSky;
        face += code < kPassage;
        passage += isPassage(code) && code != kMixed;
    }
};

Kinds kindsOf(const RadianceCascades::State& state) {
    Kinds kinds;
    for (const std::uint32_t code : state.faces.shared) kinds.add(code);
    for (const LevelData& level : state.levels) {
        for (const std::uint32_t code : level.shared) kinds.add(code);
    }
    return kinds;
}

// New sun and sky, as RadianceCascades::setLight sets them when no segment changes.
void newLight(RadianceCascades::State& state, const ShadeOptions& shading) {
    state.shading = shading;
    updateFaceLight(state);
}

TEST(CascadesShared, SharedCodesGiveTheLightOfEveryCodeOnTheCottage) {
    auto scene =
        loadVoxelScene(std::string(LUXEL_SOURCE_DIR) + "/scenes/voxel/cottage.json", 64, 36);
    ASSERT_TRUE(scene.ok()) << scene.error().message();
    auto shared = buildCascadeState(scene->world, &scene->textures, scene->shading);
    auto plain = buildCascadeState(scene->world, &scene->textures, scene->shading);
    const Kinds kinds = kindsOf(*shared);
    EXPECT_GT(kinds.mixed, 0);
    EXPECT_GT(kinds.further, kinds.mixed);  // most entries share a code
    EXPECT_GT(kinds.sky, 0);
    EXPECT_GT(kinds.face, 0);
    EXPECT_GT(kinds.passage, 0);  // a window's chain, walked once for all its corners
    clearShared(*plain);
    expectSameLightAfterPasses(*shared, *plain, 3);

    ShadeOptions evening = scene->shading;
    evening.sunDirection = {-0.7f, 0.35f, 0.2f};
    evening.skyTop = evening.skyTop * 0.5f;
    newLight(*shared, evening);
    newLight(*plain, evening);
    expectSameLightAfterPasses(*shared, *plain, 2);
}

TEST(CascadesShared, SharedCodesGiveTheLightOfEveryCodeUnderGlass) {
    const VoxelWorld world = floorWithGlass();
    ShadeOptions shading = plainLight(0.7f, Rgb(0.0f), Rgb(0.8f, 0.9f, 1.0f));
    shading.sunIrradiance = Rgb(3.0f);
    shading.sunDirection = {0.4f, 1.0f, 0.3f};
    ASSERT_TRUE(shading.materials.setSlot(0, glass()).ok());
    auto shared = buildCascadeState(world, nullptr, shading);
    auto plain = buildCascadeState(world, nullptr, shading);
    EXPECT_GT(shared->passages.size(), 0u);
    EXPECT_GT(kindsOf(*shared).passage, 0);
    clearShared(*plain);
    expectSameLightAfterPasses(*shared, *plain, 3);

    ShadeOptions low = shading;
    low.sunDirection = {-0.5f, 0.3f, 0.6f};
    low.skyModel = ShadeOptions::SkyModel::Preetham;
    newLight(*shared, low);
    newLight(*plain, low);
    expectSameLightAfterPasses(*shared, *plain, 3);
}

TEST(CascadesShared, StreamsThatWouldPassTheMemoryLimitAreNotMade) {
    auto scene =
        loadVoxelScene(std::string(LUXEL_SOURCE_DIR) + "/scenes/voxel/cottage.json", 64, 36);
    ASSERT_TRUE(scene.ok()) << scene.error().message();
    auto shared = buildCascadeState(scene->world, &scene->textures, scene->shading);
    auto tight = buildCascadeState(scene->world, &scene->textures, scene->shading);
    ASSERT_FALSE(tight->faces.shared.empty());
    // (Each state numbers its passages as its cast found them: the streams are compared with the
    // state's own.)
    const std::vector<std::uint32_t> faceShared = tight->faces.shared,
                                     faceMixed = tight->faces.mixed;
    std::vector<std::vector<std::uint32_t>> levelShared, levelMixed;
    for (const LevelData& level : tight->levels) {
        levelShared.push_back(level.shared);
        levelMixed.push_back(level.mixed);
    }
    // No room beside the estimate and the passages: none made, the old ones freed.
    tight->memoryLimit = tight->plannedBytes + tight->passages.size() * sizeof(Passage);
    EXPECT_FALSE(findSharedCodes(*tight));
    EXPECT_TRUE(tight->faces.shared.empty() && tight->faces.mixed.empty());
    EXPECT_EQ(tight->faces.shared.capacity(), 0u);
    for (const LevelData& level : tight->levels) {
        EXPECT_TRUE(level.shared.empty() && level.mixed.empty() && level.sharedStart.empty());
    }
    // The pass merges from the codes: the same light.
    expectSameLightAfterPasses(*shared, *tight, 2);
    // With room again they are made, the same as at the build.
    tight->memoryLimit = shared->memoryLimit;
    EXPECT_TRUE(findSharedCodes(*tight));
    EXPECT_EQ(tight->faces.shared, faceShared);
    EXPECT_EQ(tight->faces.mixed, faceMixed);
    for (std::size_t k = 0; k < tight->levels.size(); ++k) {
        EXPECT_EQ(tight->levels[k].shared, levelShared[k]) << k;
        EXPECT_EQ(tight->levels[k].mixed, levelMixed[k]) << k;
    }
}

}  // namespace
