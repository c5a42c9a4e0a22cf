// MagicaVoxel materials (MATL chunks) and palette alpha -> luxel voxel materials (material.h).
// The mapping table: docs/scene-format-voxel.md; what luxel cannot show becomes a warning naming
// the feature and what it became.
#pragma once

#include <array>
#include <map>
#include <string>
#include <vector>

#include "luxel/voxel/material.h"
#include "luxel/voxel/voxel_world.h"
#include "voxel/vox_chunks.h"

namespace luxel::voxel::vox {

// Collects "MATL 37: _media approximated as diffuse"-style warnings, one line per message with
// every id it applies to ("MATL 3, 9 and 12: ...").
class FeatureWarnings {
  public:
    // `id` < 0: a remark about the whole `what`, printed without ids.
    void add(const std::string& what, const std::string& message, int id);
    void lines(std::vector<std::string>& out) const;

  private:
    std::map<std::pair<std::string, std::string>, std::vector<int>> ids_;
    std::vector<std::pair<std::string, std::string>> order_;
};

// What each colour index's voxels become.
struct PaletteMapping {
    static constexpr int kPlain = -1;  // a plain block (alpha 255)
    static constexpr int kSkip = -2;   // left out (palette alpha 0)
    std::array<int, 256> slot{};       // kPlain, kSkip or an index into `materials`
    std::vector<Material> materials;   // distinct materials, named "vox N" (N: first index)
};

// Maps the colour indices that voxels use (`used`); `matl` holds the MATL dicts by material id
// (= colour index). Identical materials share one entry; beyond kMaxTextures entries the least
// used become plain blocks (with a warning).
PaletteMapping mapPalette(const std::array<Voxel, 256>& palette, const std::map<int, Dict>& matl,
                          const std::array<std::uint64_t, 256>& used, FeatureWarnings& warnings);

// The MATL dict that describes `material` on a voxel of sRGB colour `colour` (export).
Dict matlFor(const Material& material, Voxel colour);

// Emission of an `_emit` material: linear colour x kEmitScale x _emit x 2^_flux (+ _ldr x colour).
inline constexpr float kEmitScale = 4.0f;

}  // namespace luxel::voxel::vox
