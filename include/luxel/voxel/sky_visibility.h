// Sky visibility (ambient occlusion) for voxel worlds: the cheap baseline of voxel global
// illumination, measured against the path tracer (docs/algorithms/voxel-sky-visibility.md).
//
// At a surface point, N cosine-weighted rays of length R (voxels; infinity allowed) estimate the
// fraction V of the cosine-weighted hemisphere that sees the sky, and the sky light those rays see
// (the scene's gradient sky, skyColor in shading.h). The renderer shades each primary hit
// (render.samples rays per pixel, the pixel centre by default) with the path tracer's material
// model (its diffuse lobe x (direct sun with shadow rays + the sky light of the escaping rays +
// the emission of the emissive voxels the rays meet within R) + emission + the specular lobe's
// sun highlight and split-sum reflection + transmission followed through the medium;
// src/voxel/solver_surface.h). With R = infinity and Lambertian materials this is the path tracer
// with maxBounces = 1 (same mean; emitters are found by these rays only, so small ones are noisier
// than the path tracer's sampled ones); a finite R counts rays that meet nothing within R as seeing
// the sky (ambient occlusion). Random numbers come from the path tracer's counter-based generator
// keyed by (seed, pixel), so images are identical for any thread count.
#pragma once

#include <cstdint>

#include "luxel/core/error.h"
#include "luxel/core/image.h"
#include "luxel/core/vec.h"
#include "luxel/voxel/camera.h"
#include "luxel/voxel/dda.h"
#include "luxel/voxel/path_trace_rng.h"
#include "luxel/voxel/shading.h"
#include "luxel/voxel/texture_set.h"
#include "luxel/voxel/voxel_world.h"

namespace luxel::voxel {

inline constexpr int kMaxSkyRays = 1 << 16;  // rays per pixel

struct SkyVisibilityOptions {
    int rays = 16;              // cosine-weighted rays per point, 1..kMaxSkyRays
    double radius = kInfinity;  // ray length in voxels, > 0 (infinity: true sky visibility)
    std::uint64_t seed = 1;
};

// The options and the scene light (as validatePathTrace checks it); the error names the field.
Status validateSkyVisibility(const ShadeOptions& shading, const SkyVisibilityOptions& options);

struct SkyVisibility {
    double visibility = 0.0;  // V: the fraction of the rays that met nothing within the radius
    Rgb skyLight;             // sum over escaping rays of the sky they see, over the ray count
    Rgb emitterLight;         // sum over rays that meet an emissive face of its emission, likewise
};

// The estimate at `point` on a face with axis-aligned outward `normal`, drawing options.rays
// direction pairs from `rng`. The rays start on the face (the DDA's start-cell rule puts them in
// the cell in front). `options` must be valid.
SkyVisibility estimateSkyVisibility(const VoxelWorld& world, const TextureSet* textures,
                                    Vec3d point, Int3 normal, const ShadeOptions& shading,
                                    const SkyVisibilityOptions& options, PathRng& rng);

struct SkyVisibilityImage {
    Image radiance;    // linear RGB
    Image visibility;  // V per pixel, one channel (1 where the primary ray sees the sky)
};

// render.samples primary rays per pixel (shading.samplesPerPixel; one: the pixel centre),
// shaded as described above and averaged; rows in parallel.
Result<SkyVisibilityImage> renderSkyVisibility(const VoxelWorld& world, const Camera& camera,
                                               const ShadeOptions& shading,
                                               const SkyVisibilityOptions& options,
                                               const TextureSet* textures = nullptr);

}  // namespace luxel::voxel
