// Packing materials for the GPU voxel renderer.
#include "voxel/material_gpu.h"

namespace luxel::voxel {
namespace {

gpu::shared::VoxelMaterial gpuMaterial(const Material& m, bool own) {
    gpu::shared::VoxelMaterial g{};
    g.albedoR = m.albedo.r, g.albedoG = m.albedo.g, g.albedoB = m.albedo.b;
    g.metallic = m.metallic;
    g.roughness = m.roughness, g.ior = m.ior, g.transmission = m.transmission;
    g.flags = (m.proceduralTexture ? LUXEL_VOXEL_MATERIAL_PROCEDURAL : 0u) |
              (own ? LUXEL_VOXEL_MATERIAL_OWN : 0u);
    g.absorptionR = m.absorption.r, g.absorptionG = m.absorption.g, g.absorptionB = m.absorption.b;
    g.emissionR = m.emission.r, g.emissionG = m.emission.g, g.emissionB = m.emission.b;
    return g;
}

}  // namespace

std::vector<gpu::shared::VoxelMaterial> gpuMaterials(const MaterialTable& table) {
    std::vector<gpu::shared::VoxelMaterial> out(LUXEL_VOXEL_MATERIALS);
    for (int slot = 0; slot < LUXEL_VOXEL_PLAIN_MATERIAL; ++slot) {
        out[slot] = gpuMaterial(table.forSlot(slot), table.hasSlot(slot));
    }
    out[LUXEL_VOXEL_PLAIN_MATERIAL] = gpuMaterial(table.plain(), false);
    return out;
}

}  // namespace luxel::voxel
