// A lighting pass merges only the entries a chain from a face reaches
// (src/voxel/cascades/cascade_demand.h; docs/algorithms/voxel-radiance-cascades.md §5): the faces'
// irradiance after several passes equals, to the bit, what merging every entry of every level
// gives, on the cottage (chains through its glass windows) and on a floor with glass after new
// light casts the segments again; the demand leaves entries out; and new light finds the sky of
// the bins a pass reads again.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <memory>
#include <numeric>
#include <string>

#include "luxel/voxel/voxel_scene.h"
#include "voxel/cascade_states.h"
#include "voxel/cascades/cascade_demand.h"
#include "voxel/cascades/cascade_shared.h"
#include "voxel/cascades/cascade_state.h"
#include "voxel/plain_light_worlds.h"

namespace {

using namespace luxel;
using namespace luxel::voxel;
using namespace luxel::voxel::cascades;
using namespace luxel::voxel::test;

// Every entry of every level demanded, with the sky of every bin: the pass as it was before the
// demand.
void demandEverything(RadianceCascades::State& state) {
    for (LevelData& level : state.levels) {
        level.sky = skyMeans(level.bins, state.shading);
        std::fill(level.demand.begin(), level.demand.end(), ~std::uint64_t(0));
        level.demandProbes.resize(std::size_t(level.level.probeCount()));
        std::iota(level.demandProbes.begin(), level.demandProbes.end(), 0);
    }
    findSharedCodes(state);  // the merge's stream follows the demand
}

// Demanded entries over all entries, over the levels.
double demandedShare(const RadianceCascades::State& state) {
    double demanded = 0, all = 0;
    for (const LevelData& level : state.levels) {
        for (std::uint64_t word : level.demand) demanded += std::popcount(word);
        all += 64.0 * double(level.demand.size());
    }
    return demanded / all;
}

TEST(CascadesDemand, DemandedEntriesGiveTheLightOfEveryEntryOnTheCottage) {
    auto scene =
        loadVoxelScene(std::string(LUXEL_SOURCE_DIR) + "/scenes/voxel/cottage.json", 64, 36);
    ASSERT_TRUE(scene.ok()) << scene.error().message();
    auto demanded = buildCascadeState(scene->world, &scene->textures, scene->shading);
    auto every = buildCascadeState(scene->world, &scene->textures, scene->shading);
    EXPECT_GT(demanded->passages.size(), 0u);  // chains through the windows
    const double share = demandedShare(*demanded);
    EXPECT_GT(share, 0.05);
    EXPECT_LT(share, 0.9);
    demandEverything(*every);
    expectSameLightAfterPasses(*demanded, *every, 4);
}

TEST(CascadesDemand, ANewCastFindsTheDemandAgain) {
    const VoxelWorld world = floorWithGlass();
    ShadeOptions clear = plainLight(0.7f, Rgb(0.0f), Rgb(0.8f, 0.9f, 1.0f));
    clear.sunIrradiance = Rgb(3.0f);
    clear.sunDirection = {0.4f, 1.0f, 0.3f};
    ASSERT_TRUE(clear.materials.setSlot(0, glass()).ok());
    ShadeOptions opaque = clear;
    opaque.refraction = false;  // the glass stops the segments: other codes, other demand

    auto demanded = buildCascadeState(world, nullptr, clear);
    const std::vector<std::uint64_t> before = demanded->levels.front().demand;
    // As RadianceCascades::setLight does for light that changes what passes glass.
    demanded->shading = opaque;
    demanded->faces.clearEmitterLight();
    ASSERT_TRUE(buildSegments(*demanded).ok());
    updateFaceLight(*demanded);
    EXPECT_NE(demanded->levels.front().demand, before);

    auto every = buildCascadeState(world, nullptr, opaque);
    demandEverything(*every);
    expectSameLightAfterPasses(*demanded, *every, 3);
}

// New light finds the sky again for the bins a pass reads: a Preetham sky, which follows the sun.
TEST(CascadesDemand, NewLightFindsTheSkyOfTheDemandedBinsAgain) {
    const VoxelWorld world = floorWithGlass();
    ShadeOptions first = plainLight(0.7f, Rgb(0.0f), Rgb(0.8f, 0.9f, 1.0f));
    first.skyModel = ShadeOptions::SkyModel::Preetham;
    first.sunDirection = {0.4f, 1.0f, 0.3f};
    ShadeOptions second = first;
    second.sunDirection = {-0.6f, 0.5f, 0.1f};
    auto state = buildCascadeState(world, nullptr, first);
    std::vector<std::vector<Rgb>> before;
    for (const LevelData& level : state->levels) before.push_back(level.sky);
    state->shading = second;  // as RadianceCascades::setLight does when no segment changes
    updateFaceLight(*state);
    int changed = 0, read = 0;
    for (std::size_t k = 0; k < state->levels.size(); ++k) {
        const LevelData& level = state->levels[k];
        const std::vector<Rgb> full = skyMeans(level.bins, second);
        const std::vector<bool> demanded = demandedBins(*state, k);
        for (int b = 0; b < level.bins.count(); ++b) {
            if (!demanded[b]) continue;
            ++read;
            for (int c = 0; c < 3; ++c) ASSERT_EQ(level.sky[b][c], full[b][c]) << k << " " << b;
            changed += !(level.sky[b][0] == before[k][b][0]);
        }
    }
    EXPECT_GT(read, 0);
    EXPECT_GT(changed, read / 2);
}

}  // namespace
