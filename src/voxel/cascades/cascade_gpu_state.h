// What RadianceCascadesGpu keeps on the device (radiance_cascades_gpu.h): the lighting passes'
// buffers (cascade_gpu.cpp) and the picture's (cascade_picture_gpu.cpp).
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "../../gpu/shaders/shared/voxel_cascades_layout.h"
#include "cascade_picture_gpu.h"
#include "cascade_state.h"
#include "luxel/voxel/radiance_cascades_gpu.h"

namespace luxel::voxel {

struct RadianceCascadesGpu::Impl {
    gpu::Context* context = nullptr;
    RadianceCascades::State* state = nullptr;
    std::shared_ptr<gpu::Buffer> codes, corners, light, sky, means, radiance, solidAngle, faceInfo,
        cosineBins;
    gpu::Program *outgoing = nullptr, *merge = nullptr, *childMean = nullptr, *gather = nullptr;
    std::vector<std::uint32_t> codeOffset, cornerOffset, radianceOffset, meanOffset, skyOffset,
        solidAngleOffset;
    std::uint32_t faceSkyOffset = 0, faceCornerOffset = 0;
    int casts = 0;  // the state's casts its codes were uploaded from
    gpu::shared::CascadeGatherParams gatherParams{};
    std::unique_ptr<cascades::PictureGpu> picture;  // null until the first render
    VoxelGpuRenderer* uploadedWorld = nullptr;      // useUploadedWorld's, else the picture's own
};

}  // namespace luxel::voxel
