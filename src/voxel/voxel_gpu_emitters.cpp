// VoxelGpuRenderer's light from emissive voxels: the lists of EmitterLights (built on the CPU
// from the world given to create, as render() builds them) uploaded to bindings 15..17
// (shared/emitter_light.h), again only when the world or the materials changed.
#include "voxel/voxel_gpu_internal.h"

namespace luxel::voxel {

using voxel_gpu::bytesOf;
using voxel_gpu::sameBytes;

Status VoxelGpuRenderer::State::setEmitterArrays(const std::vector<std::uint32_t>& offsets,
                                                 const std::vector<std::uint32_t>& list,
                                                 const std::vector<EmitterFace>& faces) {
    // A buffer holds at least one element: empty arrays go up as one-element stand-ins.
    const std::vector<std::uint32_t> noOffsets{0u, 0u}, noList{0u};
    const std::vector<EmitterFace> noFaces(1);
    const std::span<const std::byte> data[3] = {bytesOf(offsets.empty() ? noOffsets : offsets),
                                                bytesOf(list.empty() ? noList : list),
                                                bytesOf(faces.empty() ? noFaces : faces)};
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
    return setEmitterArrays({}, {}, {});
}

Status VoxelGpuRenderer::State::prepareEmitters(
    const ShadeOptions& options, const std::vector<shared::VoxelMaterial>& gpuMaterials) {
    if (!(options.lighting == ShadeOptions::Lighting::Physical && options.emitterLight)) {
        return Ok{};
    }
    voxel_gpu::EmitterKey key{options.emitterLights, generation, gpuMaterials};
    if (emitterKey && emitterKey->given == key.given &&
        (key.given || (emitterKey->generation == key.generation &&
                       sameBytes(emitterKey->materials, key.materials)))) {
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
    if (Status st = setEmitterArrays(lights->cellOffsets(), lights->cellFaces(), lights->faces());
        !st) {
        return st;
    }
    emitterKey = std::move(key);
    return Ok{};
}

}  // namespace luxel::voxel
