// Images from the voxel renderer: the pixel loop around shadeRay.
#include "luxel/voxel/render_image.h"

#include <cmath>
#include <optional>

#include "luxel/core/parallel.h"

namespace luxel::voxel {

RayCone primaryCone(const Camera& camera) {
    const double tanHalf = std::tan(camera.fovYDegrees() * 0.5 * 3.14159265358979323846 / 180.0);
    return {0.0, 2.0 * tanHalf / camera.height()};
}

Rgb shadePixel(const VoxelWorld& world, const Camera& camera, int px, int py,
               const ShadeOptions& options, const TextureSet* textures) {
    return shadeRay(world, camera.primaryRay(px, py), primaryCone(camera), options, textures);
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
