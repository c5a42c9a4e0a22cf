// Images from the voxel renderer: the pixel loop around shadeRay, with stratified samples per
// pixel (shared/pixel_samples.h, the positions the GPU uses too).
#include "luxel/voxel/render_image.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "gpu/shaders/shared/pixel_samples.h"
#include "luxel/core/parallel.h"
#include "luxel/voxel/dda.h"
#include "voxel/shading_physical.h"

namespace luxel::voxel {

RayCone primaryCone(const Camera& camera) {
    const double tanHalf = std::tan(camera.fovYDegrees() * 0.5 * 3.14159265358979323846 / 180.0);
    return {0.0, 2.0 * tanHalf / camera.height()};
}

int samplesPerPixel(const ShadeOptions& options) {
    return std::clamp(options.samplesPerPixel, 1, kMaxSamplesPerPixel);
}

Ray pixelSampleRay(const Camera& camera, int px, int py, int k, int n) {
    const gpu::shared::vec2 o = gpu::shared::pixelSampleOffset(
        static_cast<std::uint32_t>(px), static_cast<std::uint32_t>(py), k, n);
    return camera.rayAt(px + double(o.x), py + double(o.y));
}

namespace {

// shadePixel, with the first sample's first cast made already when `primary` is given.
Rgb shadeSamples(const VoxelWorld& world, const Camera& camera, int px, int py,
                 const ShadeOptions& options, const TextureSet* textures, const Hit* primary) {
    const int n = samplesPerPixel(options);
    // Each of n samples stands for 1/n of the pixel: its cone is 1/sqrt(n) as wide.
    RayCone cone = primaryCone(camera);
    cone.spread /= std::sqrt(double(n));
    Rgb sum;
    // The pixel's index keys its sky ambient rays' numbers, as voxel_render.comp.glsl's.
    const auto pixel = static_cast<std::uint32_t>(py) * static_cast<std::uint32_t>(camera.width()) +
                       static_cast<std::uint32_t>(px);
    for (int k = 0; k < n; ++k) {
        sum += shadeRay(world, pixelSampleRay(camera, px, py, k, n), cone, options, textures,
                        {pixel, static_cast<std::uint32_t>(k), k == 0 ? primary : nullptr});
    }
    return n == 1 ? sum : sum * (1.0f / float(n));
}

// A row of one-sample pixels: their camera rays cast together first, 64 at a time sharing one
// frustum walk (castCameraRays, docs/algorithms/voxel-traversal.md §4.6), each as its lighting
// model casts it (the physical model normalises the direction), then shaded with that hit.
void shadeRow(const VoxelWorld& world, const Camera& camera, int py, const ShadeOptions& options,
              const TextureSet* textures, Image& image, std::vector<Ray>& rays,
              std::vector<Hit>& hits, std::vector<std::uint8_t>& cast) {
    const int w = camera.width();
    const bool physical = options.lighting == ShadeOptions::Lighting::Physical;
    rays.resize(static_cast<std::size_t>(w));
    hits.resize(rays.size());
    cast.assign(rays.size(), 1);
    for (int x = 0; x < w; ++x) {
        Ray r = pixelSampleRay(camera, x, py, 0, 1);
        // The physical model shades a ray without a unit direction as sky, without a cast.
        if (physical && !physicalRayDirection(r.direction, r.direction)) cast[x] = 0;
        rays[x] = r;
    }
    castCameraRays(world, rays, hits, kInfinity, options.stepCap);
    for (int x = 0; x < w; ++x) {
        image.setRgb(
            x, py,
            shadeSamples(world, camera, x, py, options, textures, cast[x] ? &hits[x] : nullptr));
    }
}

}  // namespace

Rgb shadePixel(const VoxelWorld& world, const Camera& camera, int px, int py,
               const ShadeOptions& options, const TextureSet* textures) {
    return shadeSamples(world, camera, px, py, options, textures, nullptr);
}

PreparedShading::PreparedShading(const VoxelWorld& world, const TextureSet* textures,
                                 const ShadeOptions& options)
    : options_(options) {
    if (options.lighting != ShadeOptions::Lighting::Physical) return;
    if (!options.sunVisibility) {
        SunLight sun{{options.sunDirection.x, options.sunDirection.y, options.sunDirection.z},
                     options.sunAngularRadius};
        Result<SunVisibility> built =
            SunVisibility::build(world, textures, sun, options.shadowSettings);
        if (built) {
            visibility_.emplace(std::move(*built));
            options_.sunVisibility = &*visibility_;
        }
    }
    if (options.emitterLight && !options.emitterLights) {
        emitters_.emplace(EmitterLights::build(world, options.materials));
        options_.emitterLights = &*emitters_;
    }
}

Image render(const VoxelWorld& world, const Camera& camera, const ShadeOptions& options,
             const TextureSet* textures) {
    const PreparedShading prepared(world, textures, options);
    const ShadeOptions& resolved = prepared.options();
    Image image(camera.width(), camera.height(), 3);
    // Camera rays cast a row at a time where that paid (docs/algorithms/voxel-traversal.md §4.6,
    // "The picture path"): one sample per pixel, from a camera inside the world (terrain's
    // picture about 10% less CPU; cottage's, from outside, 2% more).
    const Vec3d p = camera.position();
    const Int3 size = world.size();
    const bool rows = samplesPerPixel(resolved) == 1 && p.x >= 0.0 && p.y >= 0.0 && p.z >= 0.0 &&
                      p.x < size.x && p.y < size.y && p.z < size.z;
    parallelForRange(camera.height(), 1, [&](int begin, int end) {
        std::vector<Ray> rays;
        std::vector<Hit> hits;
        std::vector<std::uint8_t> cast;
        for (int y = begin; y < end; ++y) {
            if (rows) {
                shadeRow(world, camera, y, resolved, textures, image, rays, hits, cast);
                continue;
            }
            for (int x = 0; x < camera.width(); ++x) {
                image.setRgb(x, y, shadePixel(world, camera, x, y, resolved, textures));
            }
        }
    });
    return image;
}

}  // namespace luxel::voxel
