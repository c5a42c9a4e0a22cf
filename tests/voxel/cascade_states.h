// The voxel radiance cascades' state for tests that reach inside it (the pass's demand, the near
// emitters' lines, refused casts): built as RadianceCascades::create builds it (faces, segments,
// the faces' light), without a lighting pass.
#pragma once

#include <gtest/gtest.h>

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

}  // namespace luxel::voxel::test
