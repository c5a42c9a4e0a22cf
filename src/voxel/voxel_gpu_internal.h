// VoxelGpuRenderer's state and the helpers its files share: voxel_gpu.cpp uploads the world,
// voxel_gpu_shadows.cpp the sun visibility arrays, voxel_gpu_render.cpp dispatches the passes.
#pragma once

#include <array>
#include <cstdint>
#include <cstring>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "gpu/shaders/shared/voxel_layout.h"
#include "luxel/gpu/context.h"
#include "luxel/voxel/emitter_light.h"
#include "luxel/voxel/voxel_gpu.h"
#include "voxel/shadows/shadow_upload.h"

namespace luxel::voxel {

namespace shared = gpu::shared;

namespace voxel_gpu {

// Chunks (or bricks, with 4) covering `size`, per axis, and their product.
Int3 chunkCounts(Int3 size, int chunk);
std::uint64_t chunkTotal(Int3 chunks);

template <typename T>
std::span<const std::byte> bytesOf(const std::vector<T>& v) {
    return std::as_bytes(std::span(v));
}

// Whether two arrays of plain structs hold the same bytes.
template <typename T>
bool sameBytes(const std::vector<T>& a, const std::vector<T>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

constexpr std::uint64_t kMaterialBytes = LUXEL_VOXEL_MATERIALS * sizeof(shared::VoxelMaterial);

// What the uploaded shadow arrays were built from.
struct ShadowKey {
    const SunVisibility* given = nullptr;  // options.sunVisibility, or null when built here
    Vec3d direction;
    double angularRadius = 0.0;
    ShadowSettings settings;
    bool matches(const ShadowKey& o) const {
        return given == o.given && direction.x == o.direction.x && direction.y == o.direction.y &&
               direction.z == o.direction.z && angularRadius == o.angularRadius &&
               settings == o.settings;
    }
};

// What the uploaded emitter lists were built from: the world's version and the materials (the
// emission they give), or the lists the options gave.
struct EmitterKey {
    const EmitterLights* given = nullptr;
    std::uint64_t generation = 0;
    std::vector<shared::VoxelMaterial> materials;
};
}  // namespace voxel_gpu

struct VoxelGpuRenderer::State {
    gpu::Context* context = nullptr;
    Int3 size;
    int chunkSize = 0;
    Int3 chunks;
    int textureCount = 0;
    std::uint64_t bytes = 0;
    std::shared_ptr<gpu::Buffer> params, voxels, chunkSolid, brickMasks, brickReach, textureInfo,
        texels, srgb, output, materials;
    std::uint64_t outputBytes = 0;
    gpu::Program* program = nullptr;
    VoxelGpuUploads sent;          // bytes sent to the device so far, by kind
    std::uint64_t generation = 1;  // +1 per updateRegion that re-sent chunks
    // What params and materials hold now (empty: unknown), so unchanged ones are not sent again.
    std::vector<std::byte> paramsHeld;
    std::vector<shared::VoxelMaterial> materialsHeld;
    gpu::Program* castProgram = nullptr;
    bool reachCurrent = false;
    // The world and textures given to create (sun visibility is built from them).
    const VoxelWorld* sourceWorld = nullptr;
    const TextureSet* sourceTextures = nullptr;
    std::uint64_t limit = 0;  // device memory the renderer may use (0: unknown)
    // Sun visibility arrays at bindings 11..14 (placeholders until a method needs them), and
    // what they were built from.
    std::array<std::shared_ptr<gpu::Buffer>, 4> shadow;
    std::uint64_t shadowBytes = 0;
    std::optional<voxel_gpu::ShadowKey> shadowKey;

    // Light from emissive voxels at bindings 15..17 (voxel_gpu_emitters.cpp): the grid's offsets,
    // lists and faces (placeholders until physical lighting asks for it), what they were built
    // from, and their floor.
    std::array<std::shared_ptr<gpu::Buffer>, 3> emitters;
    std::optional<voxel_gpu::EmitterKey> emitterKey;
    float emitterFloor = kEmitterFloor;
    std::uint64_t emitterBytes = 0;
    bool emittersEmpty = true;
    // Sends `data` to `buffer` at `offset`, counted in `counter`.
    Status send(gpu::Buffer& buffer, std::span<const std::byte> data, std::uint64_t& counter,
                std::uint64_t offset = 0) {
        if (Status st = context->upload(buffer, data, offset); !st) return st;
        counter += data.size();
        return Ok{};
    }

    template <typename T>
    Result<std::shared_ptr<gpu::Buffer>> uploaded(const std::vector<T>& data) {
        auto b = context->createBuffer(data.size() * sizeof(T));
        if (!b) return b.error();
        if (Status st = send(**b, voxel_gpu::bytesOf(data), sent.shadows); !st) return st.error();
        return *b;
    }

    // The parameters, unless the buffer holds these already (voxel_gpu_render.cpp).
    Status sendParams(const shared::VoxelRenderParams& p);
    // The world part of the parameters (the rest is filled per render).
    void fillWorld(shared::VoxelRenderParams& p, int stepCap) const;

    // The emitter lists options' physical lighting needs (voxel_gpu_emitters.cpp), built on the
    // CPU as render() does (or taken from options.emitterLights) and uploaded, unless the same
    // ones are already there; placeholders when none are needed yet.
    Status prepareEmitters(const ShadeOptions& options,
                           const std::vector<shared::VoxelMaterial>& gpuMaterials);
    Status setEmitterArrays(const std::vector<std::uint32_t>& offsets,
                            const std::vector<std::uint32_t>& list,
                            const std::vector<EmitterFace>& faces);
    Status setEmitterPlaceholders();
    // voxel_gpu_shadows.cpp.
    Status setShadowArrays(const ShadowUpload& u);
    // The arrays options' sun visibility needs, built on the CPU as render() does (or taken from
    // options.sunVisibility) and uploaded, unless the same ones are already there.
    Status prepareShadows(const ShadeOptions& options);

    // Brick masks and reach of the whole world (a fraction of the voxel data: 16 bytes per 64
    // voxels), re-sent after every edit. The reach goes as it is stored: 8 planes of bytes
    // (VoxelWorld::brickReachData), read as words by voxel_world_access.glsl.
    Status uploadBricks(const VoxelWorld& world);
    Status uploadChunkSolid(const VoxelWorld& world);
    // Uploads chunks [cx0, cx1) of row (cy, cz): contiguous in the GPU layout.
    Status uploadChunkRow(const VoxelWorld& world, int cx0, int cx1, int cy, int cz);
};

}  // namespace luxel::voxel
