// Images from the voxel renderer: the pixel loop around shadeRay, with stratified samples per
// pixel (shared/pixel_samples.h, the positions the GPU uses too).
#include "luxel/voxel/render_image.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "gpu/shaders/shared/pixel_samples.h"
#include "luxel/core/parallel.h"

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

Rgb shadePixel(const VoxelWorld& world, const Camera& camera, int px, int py,
               const ShadeOptions& options, const TextureSet* textures) {
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
                        {pixel, static_cast<std::uint32_t>(k)});
    }
    return n == 1 ? sum : sum * (1.0f / float(n));
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
    parallelForRange(camera.height(), 1, [&](int begin, int end) {
        for (int y = begin; y < end; ++y) {
            for (int x = 0; x < camera.width(); ++x) {
                image.setRgb(x, y, shadePixel(world, camera, x, y, resolved, textures));
            }
        }
    });
    return image;
}

}  // namespace luxel::voxel
