// A moment shadow map for a directional light: an orthographic map over the world's bounds whose
// texels hold the filtered moments (z, z^2, z^3, z^4) of linear light-space depth z in [0, 1]
// (0 at the world's corner nearest the light). Depths come from rays cast from the light with the
// exact traversal (castToSurface, so cutout texels let light through), supersampled per texel,
// then filtered separably (box or Gaussian). Stored as fp32 or as 4 x 16 bit with the optimized
// quantization (Peters & Klein 2015); lookups read the same values either way.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "luxel/core/vec.h"
#include "luxel/voxel/shadows/sun_visibility.h"
#include "luxel/voxel/texture_set.h"
#include "luxel/voxel/voxel_world.h"

namespace luxel::voxel {

// The light's orthographic frame: map position ((p.u - uMin) / texel, (p.v - vMin) / texel) and
// depth (top - p.l) / range.
struct LightFrame {
    Vec3d l, u, v;  // unit: towards the light, and the map's two axes
    double uMin = 0, vMin = 0, texel = 1;
    double top = 0, range = 1;
    int size = 1;  // texels per side

    static LightFrame over(Int3 worldSize, Vec3d towardsLight, int mapSize);
    double depth(Vec3d p) const { return (top - dot(p, l)) / range; }
};

class MomentShadowMap {
  public:
    // Supersamples per texel side (2: four rays per texel).
    static constexpr int kSupersample = 2;

    static MomentShadowMap build(const VoxelWorld& world, const TextureSet* textures,
                                 Vec3d towardsLight, const ShadowSettings& settings);

    const LightFrame& frame() const { return frame_; }
    bool quantized() const { return quantized_; }
    // The moments of texel (x, y) as the lookups read them (decoded when quantized).
    std::array<float, 4> moments(int x, int y) const;
    // GPU layout: fp32, 4 words per texel (float bits); 16 bit, 2 words per texel (q0 | q1 << 16,
    // q2 | q3 << 16), rows of `size` texels.
    const std::vector<std::uint32_t>& words() const { return words_; }

    struct Lookup {
        float visibility = 1.0f;
        bool valid = false;  // p projects inside the map
    };
    // V at point p (the caller offsets it off its face) by MSM or VSM, bilinear moments, receiver
    // depth minus depthBias, moment bias and light-bleed reduction per the settings.
    Lookup visibility(Vec3d p, bool vsm, const ShadowSettings& settings) const;

  private:
    LightFrame frame_;
    bool quantized_ = false;
    std::vector<std::uint32_t> words_;
};

// The moment bias the settings ask for (their own, or the storage's default).
float momentBiasOf(const ShadowSettings& settings);

}  // namespace luxel::voxel
