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

// The penumbra-sized moment filter reads a double summed-area table the GPU lookup lacks.
inline constexpr const char* kPenumbraMsmGpuError =
    "render.shadows.msm_filter \"penumbra\" has no GPU twin (the penumbra-sized moment filter "
    "reads a double summed-area table on the CPU); use \"fixed\" on the GPU or render on the CPU";

// True when the settings ask for the penumbra-sized filter by a method that reads moments.
inline bool usesPenumbraMsm(const ShadowSettings& s) {
    return s.msmFilter == ShadowSettings::MsmFilter::PenumbraSized &&
           (s.method == ShadowMethod::Msm || s.method == ShadowMethod::Vsm ||
            s.method == ShadowMethod::Blend);
}

// Fails for Exact (no GPU twin) and for the penumbra-sized moment filter.
Result<ShadowUpload> shadowUploadOf(const SunVisibility& visibility);

}  // namespace luxel::voxel
