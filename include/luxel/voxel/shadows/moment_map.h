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

    // tanSunRadius: tan(theta_L), which the penumbra-sized filter (settings.msmFilter) needs.
    static MomentShadowMap build(const VoxelWorld& world, const TextureSet* textures,
                                 Vec3d towardsLight, const ShadowSettings& settings,
                                 double tanSunRadius = 0.0);

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

    // The penumbra-sized filter's estimate at p (needs a map built with PenumbraSized).
    struct Penumbra {
        bool blocked = false;        // the blocker search found occluders in front of p
        double blockerDepth = 0;     // their mean light-space distance above p, voxels
        double width = 0;            // full penumbra width 2 tan(theta_L) * blockerDepth, voxels
        double halfWidthTexels = 0;  // the box filter's half-width used at p
    };
    Penumbra penumbra(Vec3d p, const ShadowSettings& settings) const;

  private:
    // Mean unfiltered moments over the box [u - h, u + h] x [v - h, v + h] (map texels), clipped
    // to the map, from the summed-area table (bilinear in the table: exact for texel boxes).
    std::array<double, 4> boxMoments(double u, double v, double h) const;

    LightFrame frame_;
    double tanSun_ = 0.0;
    // Penumbra-sized filter: (size + 1)^2 prefix sums of the unfiltered moments, in double
    // (fp32 sums over a 1024^2 map would lose the moments' low digits).
    std::vector<std::array<double, 4>> sat_;
    bool quantized_ = false;
    std::vector<std::uint32_t> words_;
};

// The moment bias the settings ask for (their own, or the storage's default).
float momentBiasOf(const ShadowSettings& settings);

}  // namespace luxel::voxel
