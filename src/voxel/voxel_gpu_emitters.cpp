// VoxelGpuRenderer's light from emissive voxels: the lists of EmitterLights (built on the CPU
// from the world given to create, as render() builds them) uploaded to bindings 15..17
// (shared/emitter_light.h), again only when the world or the materials changed.
#include <cstring>

#include "voxel/voxel_gpu_internal.h"

namespace luxel::voxel {

using voxel_gpu::bytesOf;

namespace {

bool sameMaterials(const std::vector<shared::VoxelMaterial>& a,
                   const std::vector<shared::VoxelMaterial>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(a[0])) == 0;
}

}  // namespace

Status VoxelGpuRenderer::State::setEmitterArrays(const std::vector<std::uint32_t>& offsets,
                                                 const std::vector<std::uint32_t>& list,
                                                 const std::vector<EmitterFace>& faces) {
    const std::span<const std::byte> data[3] = {bytesOf(offsets), bytesOf(list), bytesOf(faces)};
    emitters = {};
    emitterBytes = 0;
    for (std::size_t i = 0; i < 3; ++i) {
        auto b = context->createBuffer(data[i].size());
        if (!b) return b.error();
        if (Status st = send(**b, data[i], sent.emitters); !st) return st;
        emitters[i] = *b;
        emitterBytes += data[i].size();
    }
    return Ok{};
}

Status VoxelGpuRenderer::State::setEmitterPlaceholders() {
    emitterKey.reset();
    emittersEmpty = true;
    return setEmitterArrays({0u, 0u}, {0u}, std::vector<EmitterFace>(1));
}

Status VoxelGpuRenderer::State::prepareEmitters(
    const ShadeOptions& options, const std::vector<shared::VoxelMaterial>& gpuMaterials) {
    if (!(options.lighting == ShadeOptions::Lighting::Physical && options.emitterLight)) {
        return Ok{};
    }
    voxel_gpu::EmitterKey key{options.emitterLights, generation, gpuMaterials};
    if (emitterKey && emitterKey->given == key.given &&
        (key.given || (emitterKey->generation == key.generation &&
                       sameMaterials(emitterKey->materials, key.materials)))) {
        return Ok{};
    }
    EmitterLights built;
    const EmitterLights* lights = options.emitterLights;
    if (!lights) {
        built = EmitterLights::build(*sourceWorld, options.materials);
        lights = &built;
    }
    emittersEmpty = lights->empty();
    emitterFloor = lights->floor();
    std::vector<std::uint32_t> offsets = lights->cellOffsets(), list = lights->cellFaces();
    std::vector<EmitterFace> faces = lights->faces();
    // Empty vectors still need a buffer of one element.
    if (offsets.empty()) offsets = {0u, 0u};
    if (list.empty()) list = {0u};
    if (faces.empty()) faces.resize(1);
    if (Status st = setEmitterArrays(offsets, list, faces); !st) return st;
    emitterKey = std::move(key);
    return Ok{};
}

}  // namespace luxel::voxel
