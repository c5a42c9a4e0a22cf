// Sky visibility and its renderer (sky_visibility.h; docs/algorithms/voxel-sky-visibility.md).
// The surface model, sun shadows and ray directions are the path tracer's (path_trace_surface.h),
// so with an infinite radius the image is the path tracer's one-reflection image in expectation.
#include <cmath>
#include <sstream>

#include "luxel/core/parallel.h"
#include "luxel/voxel/path_trace.h"
#include "luxel/voxel/render_image.h"
#include "luxel/voxel/sky_visibility.h"
#include "luxel/voxel/surface_cast.h"
#include "path_trace_surface.h"
#include "solver_sun.h"
#include "solver_surface.h"
#include "sun_disk.h"
#include "sun_ray_map.h"

namespace luxel::voxel {

namespace {

// What a reflected or transmitted ray sees along r: the sky (with the sun's disk behind a delta
// lobe), or an emissive face within the radius, as the diffuse estimate's rays see them
// (occluders within the radius are black); glass and polished metal within the radius are
// followed (solverFollows: their material, what lies behind or what they reflect) up to
// kSolverFollowDepth deep when `follow` (some material is followed).
Rgb reflectedLight(const VoxelWorld& world, const TextureSet* textures, const Ray& r, bool delta,
                   int depth, bool follow, const ShadeOptions& shading, double radius,
                   const SunRayMap& sunRayMap, PathRng& rng) {
    const bool followed = follow && depth < kSolverFollowDepth;
    if (shading.materials.anyEmission() || followed) {
        const SurfaceHit s = castToSurface(world, textures, r, shading.stepCap);
        if (s.hit.hit && s.hit.t <= radius) {
            if (followed && s.hit.normal != Int3{} && solverFollows(world, s, shading)) {
                // Sky visibility has no light for the faces it meets: none for the followed one's.
                const SolverLight behind{{},
                                         [&](const Ray& q, bool d) {
                                             return reflectedLight(world, textures, q, d && delta,
                                                                   depth + 1, follow, shading,
                                                                   radius, sunRayMap, rng);
                                         },
                                         1,
                                         1,
                                         &sunRayMap};
                return shadeSolverSurface(world, textures, s, r, shading, behind, rng);
            }
            return pathSurfaceAt(world, s, shading).emission;
        }
    } else if (surfaceRayBlocked(world, textures, r, radius, shading.stepCap)) {
        return {};
    }
    return skyColor(r.direction, shading) + (delta ? sunDiskAlong(r.direction, shading) : Rgb{});
}

// The map that proves the sun's rays open or blocked (sun_ray_map.h) for the surface's spiral and a
// followed face's single ray; none for worlds past SunRayMap::kMaxWorldVoxels, whose scan would
// cost more than a picture's rays save.
SunRayMap sunRayMapFor(const VoxelWorld& world, const TextureSet* textures,
                       const ShadeOptions& shading) {
    const Int3 size = world.size();
    if (std::int64_t(size.x) * size.y * size.z > SunRayMap::kMaxWorldVoxels) return {};
    const SunDisk sun = SunDisk::make(shading.sunDirection, shading.sunAngularRadius);
    return SunRayMap::build(world, spiralDirections(sun, {kSunDiskRays, 1}),
                            sunRaysStopAtSolids(textures, shading));
}

}  // namespace

Status validateSkyVisibility(const ShadeOptions& shading, const SkyVisibilityOptions& options) {
    if (options.rays < 1 || options.rays > kMaxSkyRays) {
        return Error("sky visibility rays must be in 1.." + std::to_string(kMaxSkyRays) + ", got " +
                     std::to_string(options.rays));
    }
    if (!(options.radius > 0.0)) {  // NaN fails too; +infinity is allowed
        std::ostringstream s;
        s << options.radius;
        return Error("sky visibility radius must be > 0 voxels (or infinite), got " + s.str());
    }
    // The scene light is the path tracer's: its check names the field.
    return validatePathTrace(shading, PathTraceOptions{});
}

SkyVisibility estimateSkyVisibility(const VoxelWorld& world, const TextureSet* textures,
                                    Vec3d point, Int3 normal, const ShadeOptions& shading,
                                    const SkyVisibilityOptions& options, PathRng& rng) {
    int escaped = 0;
    Rgb sky, emitted;
    // Emissive materials need the face a ray meets; otherwise an occlusion test is enough.
    const bool emitters = shading.materials.anyEmission();
    for (int i = 0; i < options.rays; ++i) {
        const float u1 = rng.next(), u2 = rng.next();
        const Ray ray{point, cosineDirection(normal, u1, u2)};  // unit length: t is in voxels
        if (emitters) {
            const SurfaceHit s = castToSurface(world, textures, ray, shading.stepCap);
            if (s.hit.hit && s.hit.t <= options.radius) {
                emitted += pathSurfaceAt(world, s, shading).emission;
                continue;
            }
        } else if (surfaceRayBlocked(world, textures, ray, options.radius, shading.stepCap)) {
            continue;
        }
        ++escaped;
        sky += skyColor(ray.direction, shading);
    }
    const double n = options.rays;
    return {escaped / n, sky * float(1.0 / n), emitted * float(1.0 / n)};
}

Result<SkyVisibilityImage> renderSkyVisibility(const VoxelWorld& world, const Camera& camera,
                                               const ShadeOptions& shading,
                                               const SkyVisibilityOptions& options,
                                               const TextureSet* textures) {
    if (Status s = validateSkyVisibility(shading, options); !s) return s.error();
    const int width = camera.width(), height = camera.height();
    if (std::int64_t(width) * height > kMaxPathPixels) {
        return Error("sky visibility: image " + std::to_string(width) + "x" +
                     std::to_string(height) + " has more than " + std::to_string(kMaxPathPixels) +
                     " pixels");
    }
    SkyVisibilityImage out{Image(width, height, 3), Image(width, height, 1)};
    const bool follow = solverFollowsAny(shading);
    const int samples = samplesPerPixel(shading);
    const SunRayMap sunRayMap = sunRayMapFor(world, textures, shading);
    parallelForRange(height, 1, [&](int begin, int end) {
        for (int y = begin; y < end; ++y) {
            for (int x = 0; x < width; ++x) {
                // One random stream per pixel, drawn on through its samples.
                PathRng rng(options.seed, std::uint64_t(y) * width + x, 0);
                Rgb radiance;
                double visibility = 0.0;
                for (int k = 0; k < samples; ++k) {
                    const Ray ray = pixelSampleRay(camera, x, y, k, samples);
                    const SurfaceHit s = castToSurface(world, textures, ray, shading.stepCap);
                    if (!s.hit.hit) {  // left the world (or ran past the step cap): the sky
                        radiance += skyColor(ray.direction, shading);
                        visibility += 1.0;
                    } else if (s.hit.normal != Int3{}) {  // else the camera is in a solid voxel
                        const SkyVisibility v = estimateSkyVisibility(
                            world, textures, s.hit.point, s.hit.normal, shading, options, rng);
                        visibility += v.visibility;
                        const SolverLight light{v.skyLight + v.emitterLight,
                                                [&](const Ray& r, bool delta) {
                                                    return reflectedLight(
                                                        world, textures, r, delta, 0, follow,
                                                        shading, options.radius, sunRayMap, rng);
                                                },
                                                kSunDiskRays, kSolverSpecularRays, &sunRayMap};
                        radiance +=
                            shadeSolverSurface(world, textures, s, ray, shading, light, rng);
                    }
                }
                if (samples > 1) {
                    radiance = radiance * (1.0f / float(samples));
                    visibility /= samples;
                }
                for (int c = 0; c < 3; ++c) out.radiance.at(x, y, c) = radiance[c];
                out.visibility.at(x, y, 0) = float(visibility);
            }
        }
    });
    return out;
}

}  // namespace luxel::voxel
