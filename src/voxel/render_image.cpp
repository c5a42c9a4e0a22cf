// Images from the voxel renderer: the pixel loop around shadeRay, with stratified samples per
// pixel (shared/pixel_samples.h, the positions the GPU uses too).
#include "luxel/voxel/render_image.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "gpu/shaders/shared/pixel_samples.h"
#include "luxel/core/parallel.h"
#include "luxel/voxel/emitter_light.h"

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
    for (int k = 0; k < n; ++k) {
        sum += shadeRay(world, pixelSampleRay(camera, px, py, k, n), cone, options, textures);
    }
    return n == 1 ? sum : sum * (1.0f / float(n));
}

Image render(const VoxelWorld& world, const Camera& camera, const ShadeOptions& options,
             const TextureSet* textures) {
    ShadeOptions resolved = options;
    std::optional<SunVisibility> visibility;
    if (options.lighting == ShadeOptions::Lighting::Physical && !options.sunVisibility) {
        SunLight sun{{options.sunDirection.x, options.sunDirection.y, options.sunDirection.z},
                     options.sunAngularRadius};
        Result<SunVisibility> built =
            SunVisibility::build(world, textures, sun, options.shadowSettings);
        if (built) {
            visibility.emplace(std::move(*built));
            resolved.sunVisibility = &*visibility;
        }
    }
    std::optional<EmitterLights> emitters;
    if (options.lighting == ShadeOptions::Lighting::Physical && options.emitterLight &&
        !options.emitterLights) {
        emitters.emplace(EmitterLights::build(world, options.materials));
        resolved.emitterLights = &*emitters;
    }
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
