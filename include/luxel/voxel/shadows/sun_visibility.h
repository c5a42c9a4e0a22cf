// Visibility of the sun (a disk of angular radius theta_L) from surface points of a voxel world,
// by one of several methods: the exact cone-sampled ground truth, a single hard shadow ray,
// moment shadow maps (4-moment Hamburger MSM or 2-moment VSM), the SDF soft-shadow estimator,
// the corrected MRMA blend of MSM and SDF, and block-game flood-fill light.
//
// V in [0, 1] is pure visibility (1 = fully lit); N.L is applied once by the shader, outside it.
// Design and corrected equations: docs/algorithms/voxel-shadows.md.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "luxel/core/error.h"
#include "luxel/core/vec.h"
#include "luxel/voxel/texture_set.h"
#include "luxel/voxel/voxel_world.h"

namespace luxel::voxel {

enum class ShadowMethod {
    Hard,       // one ray towards the light's centre (the renderer's original shadows)
    Exact,      // cone-sampled area-light visibility with the exact traversal (ground truth)
    Msm,        // 4-moment Hamburger moment shadow map
    Vsm,        // 2-moment variance shadow map (Chebyshev bound)
    Sdf,        // sphere-traced soft shadow on the Euclidean distance field (Aaltonen)
    Blend,      // MRMA: a * V_msm + (1 - a) * V_sdf, a in [0, 1] from a smoothstep band
    FloodFill,  // BFS light levels (the block-game baseline)
};

// "hard", "exact", "msm", "vsm", "sdf", "blend", "flood" (the scene file's and CLI's names).
const char* shadowMethodName(ShadowMethod method);
// The method of a name above; false for an unknown name.
bool parseShadowMethod(const std::string& name, ShadowMethod& method);

// The sun: direction towards it (need not be unit length) and its angular radius.
struct SunLight {
    Vec3d direction{0.0, 1.0, 0.5};
    double angularRadius = 0.0047;  // radians; the real sun is about 0.27 degrees
};

struct ShadowSettings {
    ShadowMethod method = ShadowMethod::Hard;
    int exactSamples = 256;  // Exact: rays per point, stratified over the light's cone
    // Moment shadow map (Msm, Vsm, Blend).
    int mapSize = 1024;  // texels per side of the orthographic map over the world's bounds
    enum class MomentStorage { Float32, Quantized16 } momentStorage = MomentStorage::Float32;
    enum class MomentFilter { Box, Gaussian } momentFilter = MomentFilter::Gaussian;
    double filterRadius = 2.0;  // texels: box half-width, or Gaussian sigma
    // Fixed: the filter above for every receiver (a filtered hard shadow). PenumbraSized: a box
    // whose width follows the penumbra, tan(theta_L) * (receiver - mean blocker depth), the
    // blocker depth estimated from the moments over the widest possible penumbra (moment soft
    // shadow mapping; CPU only: a double summed-area table of the unfiltered fp32 moments, so
    // momentStorage and the fixed filter do not apply to it).
    enum class MsmFilter { Fixed, PenumbraSized } msmFilter = MsmFilter::Fixed;
    double momentBias = 0.0;           // 0: the storage's documented default
    double lightBleedReduction = 0.0;  // rho in linstep(rho, 1, V); 0 = off
    double depthBias = 0.0;            // voxels, subtracted from the receiver depth
    // Voxels along the face normal that MSM and VSM receivers are moved off their face
    // (normal-offset shadows: no self-shadowing without a large depth bias). Every voxel of
    // offset moves a shadow edge by 1 / tan(sun elevation) voxels, so it is kept small.
    double normalOffset = 0.05;
    // SDF soft shadows (Sdf, Blend).
    int sdfMaxSteps = 64;
    // The same for SDF receivers: the exact cube distance needs only to leave the face.
    double sdfNormalOffset = 0.02;
    // The distance the estimator reads: Cubes, the exact distance to the voxel cubes (feature
    // transform, DistanceField::surfaceDistance); Centres, the trilinear centre field (estimate).
    enum class SdfDistance { Cubes, Centres } sdfDistance = SdfDistance::Cubes;
    // MRMA blend: a = smoothstep(blendNear, blendFar, footprint), footprint = camera distance
    // for primary rays, ray-cone width / voxel for secondary ones (docs §6).
    double blendNear = 48.0;
    double blendFar = 64.0;
    bool sdfNear = true;     // SDF near the camera and MSM far (false: the opposite split)
    bool minInBand = false;  // inside the band use min(V_msm, V_sdf) instead of the lerp

    bool operator==(const ShadowSettings&) const = default;
};

// What the renderer asks: a surface point on a voxel face, its face normal, and the footprint
// that drives the MRMA blend (camera distance for primary rays).
struct ShadowQuery {
    Vec3d point;
    Int3 normal;
    double footprint = 0.0;
};

// Peak bytes SunVisibility::build needs for a world of this size: the moment map with its filter
// copies (and summed-area table), the distance transform's working grids, the light levels.
std::uint64_t estimateSunVisibilityBytes(Int3 worldSize, const ShadowSettings& settings);

class SunVisibility {
  public:
    // Builds what the method needs (shadow map, distance field, light levels) for this world.
    // Refuses, with the numbers, when estimateSunVisibilityBytes exceeds the available memory.
    // The world and textures must outlive the object and not change (edits: rebuild).
    static Result<SunVisibility> build(const VoxelWorld& world, const TextureSet* textures,
                                       const SunLight& sun, const ShadowSettings& settings);
    SunVisibility(SunVisibility&&) noexcept;
    SunVisibility& operator=(SunVisibility&&) noexcept;
    ~SunVisibility();

    // V in [0, 1]. Points whose normal faces away from the sun are 0.
    float visibility(const ShadowQuery& query) const;

    const SunLight& sun() const;
    const ShadowSettings& settings() const;

    // What the method built, for upload to the GPU (SunVisibilityGpu, the render pass's shadow
    // bindings): null when the method does not use it.
    const class MomentShadowMap* momentMap() const;
    const class DistanceField* distanceField() const;
    const class LightLevels* lightLevels() const;
    const VoxelWorld& world() const;

  private:
    struct State;
    explicit SunVisibility(std::unique_ptr<State> state);
    std::unique_ptr<State> state_;
};

}  // namespace luxel::voxel
