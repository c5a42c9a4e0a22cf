// The voxel radiance cascades' picture on the GPU (radiance_cascades_gpu.h;
// docs/algorithms/voxel-radiance-cascades.md §4.3): what RadianceCascadesGpu keeps for it, made
// on the first render (cascade_picture_gpu.cpp).
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "../../gpu/shaders/shared/cascade_picture_layout.h"
#include "luxel/voxel/voxel_gpu.h"
#include "surface_faces.h"

namespace luxel::gpu {
class Program;
}

namespace luxel::voxel::cascades {

struct PictureGpu {
    std::unique_ptr<VoxelGpuRenderer> ownWorld;  // its own upload, unless one was given
    VoxelGpuRenderer* world = nullptr;           // the world, textures and materials on the device
    std::shared_ptr<gpu::Buffer> slots, albedo, image;
    std::uint64_t imageBytes = 0;
    // The adaptive pass's pixel list (adaptive_samples.h), grown as needed.
    std::shared_ptr<gpu::Buffer> refine;
    std::uint64_t refineBytes = 0;
    // The emitters near each face (shared/near_emitters.h), uploaded again when the CPU object
    // computed them again (FaceData::emitterVersion).
    std::shared_ptr<gpu::Buffer> emitterFar, nearOffset, nearEmitters;
    // The lamps the glossy surfaces light-sample (GlossyLamps), uploaded with them; their grid's
    // cells (0: none).
    std::shared_ptr<gpu::Buffer> glossyPicks, glossyLamps;
    Int3 lampCells;
    std::uint64_t emitterVersion = 0, nearBytes = 0;
    bool nearUploaded = false;
    std::uint64_t worldBytes = 0, tableBytes = 0;  // the estimates the memory check counts
    std::uint32_t slotMask = 0;
    gpu::Program* program = nullptr;
};

// The faces' open-addressing table (linear probing from cascadeFaceHash): a power of two of at
// least twice the faces' slots, so a probe for a missing face ends at an empty slot soon.
std::vector<gpu::shared::CascadeFaceSlot> faceSlots(const FaceTable& table);

}  // namespace luxel::voxel::cascades
