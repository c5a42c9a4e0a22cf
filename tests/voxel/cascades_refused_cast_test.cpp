// A cast of the voxel radiance cascades' segments refused for memory (its runs through glass past
// the limit; docs/algorithms/voxel-radiance-cascades.md §5) leaves every level and the faces laid
// out for the new cast, the codes it did not reach void: the faces' arrays sized for the face table
// the new light made (glass lying on a floor adds the faces under it), and no code naming a run
// through glass of the cast before, whose passages it cleared. The passes then run on what it left.
#include <gtest/gtest.h>

#include <cmath>

#include "voxel/cascade_states.h"
#include "voxel/cascades/cascade_state.h"
#include "voxel/plain_light_worlds.h"

namespace {

using namespace luxel;
using namespace luxel::voxel;
using namespace luxel::voxel::cascades;
using namespace luxel::voxel::test;

constexpr Voxel kGlass{255, 255, 255, 1};  // texture slot 0

// A white floor with a glass block lying on it and another floating above it: with refraction on,
// the floor's faces under the block join the face table and segments run through both blocks.
VoxelWorld glassOnAFloor() {
    VoxelWorld world = makeWorld({24, 12, 24});
    for (int z = 0; z < 24; ++z) {
        for (int x = 0; x < 24; ++x) {
            world.set(x, 0, z, kWhite);
            if (x >= 4 && x < 20 && z >= 4 && z < 20) world.set(x, 1, z, kGlass);
            if (x >= 2 && x < 22 && z >= 2 && z < 22) world.set(x, 7, z, kGlass);
        }
    }
    world.refreshEmptySpace();
    return world;
}

ShadeOptions glassLight(bool refraction, float absorption) {
    ShadeOptions o = plainLight(0.5f, Rgb(0.0f), Rgb(1.0f));
    EXPECT_TRUE(o.materials.setSlot(0, glass(Rgb(absorption))).ok());
    o.refraction = refraction;
    return o;
}

// Every array the passes read is laid out for the current levels and face table, and every run
// through glass a code names is one of the current passages.
void expectLaidOut(const RadianceCascades::State& state) {
    const FaceData& faces = state.faces;
    const std::size_t count = std::size_t(faces.table.size());
    ASSERT_EQ(faces.codeOffset.size(), count + 1);
    ASSERT_EQ(faces.corners.size(), count);
    ASSERT_EQ(faces.codeOffset.back(), faces.codes.size());
    const auto known = [&](std::uint32_t code) {
        return !isPassage(code) || code - kPassage < state.passages.size();
    };
    for (std::uint32_t code : faces.codes) ASSERT_TRUE(known(code)) << code;
    for (const LevelData& level : state.levels) {
        const std::size_t perBin = level.level.top ? 1 : 8;
        ASSERT_EQ(level.codes.size(),
                  std::size_t(level.level.probeCount()) * level.bins.count() * perBin);
        if (!level.level.top) {
            ASSERT_EQ(level.corners.size(), std::size_t(level.level.probeCount()));
        }
        for (std::uint32_t code : level.codes) ASSERT_TRUE(known(code)) << code;
    }
}

void expectPassesRun(RadianceCascades::State& state) {
    updateFaceLight(state);
    for (int pass = 0; pass < 3; ++pass) lightingPass(state);
    for (const Rgb& e : state.faces.irradiance) {
        ASSERT_TRUE(std::isfinite(e.r) && std::isfinite(e.g) && std::isfinite(e.b));
    }
}

TEST(CascadesRefusedCast, LeavesTheFacesOfTheNewTableLaidOut) {
    const VoxelWorld world = glassOnAFloor();
    // Without refraction nothing runs through glass: 1 KiB beside the estimate is room enough.
    CascadeOptions given;
    given.spacing = 2;
    const std::uint64_t tight = estimateCascades(world, given).bytes + 1024;
    auto state = buildCascadeState(world, nullptr, glassLight(false, 0.1f), 2, tight);
    const int opaqueFaces = state->faces.table.size();
    state->shading = glassLight(true, 0.1f);
    ASSERT_FALSE(buildSegments(*state).ok());
    EXPECT_FALSE(state->castComplete);
    EXPECT_GT(state->faces.table.size(), opaqueFaces);  // the floor under the block
    expectLaidOut(*state);
    expectPassesRun(*state);
}

TEST(CascadesRefusedCast, LeavesNoCodeOfTheLastCastsRunsThroughGlass) {
    const VoxelWorld world = glassOnAFloor();
    auto state = buildCascadeState(world, nullptr, glassLight(true, 0.1f), 2);
    ASSERT_GT(state->passages.size(), 0u);
    // New glass (another absorption) casts again, now with room for a few runs only.
    state->shading = glassLight(true, 0.3f);
    state->memoryLimit = state->plannedBytes + 1024;
    ASSERT_FALSE(buildSegments(*state).ok());
    expectLaidOut(*state);
    expectPassesRun(*state);
}

}  // namespace
