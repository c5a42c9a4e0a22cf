// The voxel radiance cascades' state for tests that reach inside it (the pass's demand, the near
// emitters' lines, refused casts): built as RadianceCascades::create builds it (faces, segments,
// the faces' light), without a lighting pass.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <memory>

#include "voxel/cascades/cascade_state.h"

namespace luxel::voxel::test {

// `spacing` 0: chosen as create() chooses it; given, a refused cast is not tried at another.
inline std::unique_ptr<RadianceCascades::State> buildCascadeState(
    const VoxelWorld& world, const TextureSet* textures, const ShadeOptions& shading,
    int spacing = 0, std::uint64_t memoryLimit = std::uint64_t(1) << 31) {
    auto state = std::make_unique<RadianceCascades::State>();
    state->world = &world;
    state->textures = textures;
    state->shading = shading;
    state->options.spacing = spacing;
    state->memoryLimit = memoryLimit;
    state->faces.bins = cascades::DirectionBins::build(cascades::kFaceBinSide);
    EXPECT_TRUE(cascades::buildSegments(*state).ok());
    cascades::updateFaceLight(*state);
    return state;
}

// Runs `passes` lighting passes on two states of one world that differ in how a pass reads them
// (its demand, its shared codes, its sky-only faces) and expects the same irradiance, in a world
// mostly lit: to the bit, or with `tolerance` within that share of the face's brightest channel.
inline void expectSameLightAfterPasses(RadianceCascades::State& a, RadianceCascades::State& b,
                                       int passes, float tolerance = 0.0f) {
    for (int i = 0; i < passes; ++i) {
        cascades::lightingPass(a);
        cascades::lightingPass(b);
    }
    ASSERT_EQ(a.faces.irradiance.size(), b.faces.irradiance.size());
    int lit = 0;
    for (std::size_t f = 0; f < b.faces.irradiance.size(); ++f) {
        const Rgb x = a.faces.irradiance[f], y = b.faces.irradiance[f];
        const float bound = tolerance * std::max(y.maxComponent(), 1e-6f);
        for (int c = 0; c < 3; ++c) {
            if (tolerance == 0.0f) {
                ASSERT_EQ(x[c], y[c]) << f;
            } else {
                ASSERT_NEAR(x[c], y[c], bound) << f << " " << c;
            }
        }
        lit += y[0] > 0.0f;
    }
    EXPECT_GT(lit, int(b.faces.irradiance.size()) / 2);  // not a dark world
}

}  // namespace luxel::voxel::test
