// The arrays and parameters of a SunVisibility in the GPU layout (shared/shadow_layout.h), for
// SunVisibilityGpu and the render pass's shadow bindings.
#pragma once

#include <cstdint>
#include <vector>

#include "gpu/shaders/shared/shadow_layout.h"
#include "luxel/core/error.h"
#include "luxel/voxel/shadows/sun_visibility.h"

namespace luxel::voxel {

struct ShadowUpload {
    gpu::shared::ShadowParams params{};
    std::vector<std::uint32_t> moments;  // one dummy word when unused
    std::vector<float> field;
    std::vector<std::uint32_t> levels;
};

// Fails for Exact (no GPU twin).
Result<ShadowUpload> shadowUploadOf(const SunVisibility& visibility);

}  // namespace luxel::voxel
