// Surface materials of voxels for physical lighting (docs/algorithms/voxel-surfaces.md): how a
// face reflects (diffuse albedo, metallic, roughness), refracts (index of refraction,
// transmission, Beer-Lambert absorption inside) and glows (emission).
//
// Materials live in a table indexed like the textures: voxel alpha 1..254 selects texture slot
// a - 1 and the material of that slot; plain blocks (alpha 255) and slots without a material
// use the table's `plain` material. A material without an image is a texture slot named
// "material:NAME" holding one white texel, whose material has `proceduralTexture` set, so the
// procedural face texture still applies as on plain blocks.
#pragma once

#include <string>
#include <vector>

#include "luxel/core/error.h"
#include "luxel/core/vec.h"

namespace luxel::voxel {

struct Material {
    std::string name;
    Rgb albedo{1.0f, 1.0f, 1.0f};  // multiplies the voxel colour (and texel): tints, darkens
    float metallic = 0.0f;         // 0 dielectric, 1 metal (reflectance = albedo, no diffuse)
    float roughness = 0.7f;        // perceptual, in [0, 1]; GGX alpha = roughness^2
    float ior = 1.5f;              // index of refraction of a dielectric, in [1, 4]
    float transmission = 0.0f;     // 0 opaque; 1 clear: what the surface does not reflect enters
    Rgb absorption{0.0f, 0.0f, 0.0f};  // sigma_a per voxel of path inside (transmissive only)
    Rgb emission{0.0f, 0.0f, 0.0f};    // linear radiance the face emits
    bool proceduralTexture = false;    // the procedural face texture modulates the colour
};

// The built-in material of plain blocks: a rough dielectric (ior 1.5, roughness 0.7), so
// terrain is lit diffusely with a faint broad highlight and mirrors nothing.
Material defaultMaterial();

// "material: " plus the name: the texture slot standing for a material without an image.
std::string materialSlotName(const std::string& materialName);

// Every field finite and in range; the error names the field ("roughness must be in 0..1,
// got 2").
Status validateMaterial(const Material& material);

class MaterialTable {
  public:
    MaterialTable();
    // The material of plain blocks and of slots without their own.
    const Material& plain() const { return plain_; }
    Status setPlain(Material material);
    // Gives texture slot `slot` (0..253) a material.
    Status setSlot(int slot, Material material);
    // The material a voxel with texture slot `slot` shows (-1: a plain block).
    const Material& forSlot(int slot) const;
    bool hasSlot(int slot) const;
    // Whether any material (plain or a slot's) emits light (kept up to date by the setters, so
    // renderers may ask per pixel).
    bool anyEmission() const { return emits_; }
    // Whether any material lets light through (transmission > 0 and not fully metallic): the
    // solvers' sun rays need to look for glass only then.
    bool anyTransmission() const { return transmits_; }
    // Slots that have a material of their own are 0..slotCount() - 1 at most.
    int slotCount() const { return static_cast<int>(slots_.size()); }

  private:
    Material plain_;
    std::vector<Material> slots_;
    std::vector<bool> set_;
    bool emits_ = false;
    bool transmits_ = false;

    void updateFlags();
};

}  // namespace luxel::voxel
