// Jittered voxel frames and their depth, for the temporal upscaler.
#include "luxel/post/voxel_frames.h"

#include <cmath>
#include <cstdint>

#include "luxel/core/parallel.h"
#include "luxel/voxel/dda.h"
#include "luxel/voxel/render_image.h"

namespace luxel::post {

voxel::Camera resizedCamera(const voxel::Camera& camera, int width, int height) {
    const Vec3d f = camera.forward();
    const double yaw = std::atan2(f.x, f.z) * 180.0 / 3.14159265358979323846;
    const double pitch = std::asin(std::clamp(f.y, -1.0, 1.0)) * 180.0 / 3.14159265358979323846;
    auto resized =
        voxel::Camera::create(camera.position(), yaw, pitch, camera.fovYDegrees(), width, height);
    return resized ? *resized : camera;
}

PinholeView viewOf(const voxel::Camera& camera) {
    return {camera.position(),
            camera.forward(),
            camera.right(),
            camera.up(),
            std::tan(camera.fovYDegrees() * 0.5 * 3.14159265358979323846 / 180.0),
            camera.width(),
            camera.height()};
}

Image renderJittered(const voxel::VoxelWorld& world, const voxel::Camera& camera,
                     const voxel::ShadeOptions& options, const voxel::TextureSet* textures,
                     Vec2d jitter) {
    // The sun's visibility and the emitters' lists, as render() builds them.
    const voxel::PreparedShading prepared(world, textures, options);
    const voxel::ShadeOptions& resolved = prepared.options();
    const voxel::RayCone cone = voxel::primaryCone(camera);
    Image image(camera.width(), camera.height(), 3);
    parallelForRange(camera.height(), 1, [&](int begin, int end) {
        for (int y = begin; y < end; ++y) {
            for (int x = 0; x < camera.width(); ++x) {
                const voxel::Ray ray = camera.rayAt(x + 0.5 + jitter.x, y + 0.5 + jitter.y);
                const auto pixel = static_cast<std::uint32_t>(y * camera.width() + x);
                image.setRgb(x, y, voxel::shadeRay(world, ray, cone, resolved, textures, {pixel}));
            }
        }
    });
    return image;
}

Image primaryDepth(const voxel::VoxelWorld& world, const voxel::Camera& camera, Vec2d jitter) {
    Image depth(camera.width(), camera.height(), 1);
    parallelForRange(camera.height(), 4, [&](int begin, int end) {
        for (int y = begin; y < end; ++y) {
            for (int x = 0; x < camera.width(); ++x) {
                const voxel::Ray ray = camera.rayAt(x + 0.5 + jitter.x, y + 0.5 + jitter.y);
                const voxel::Hit hit = voxel::castRay(world, ray);
                depth.at(x, y, 0) =
                    hit.hit ? static_cast<float>(hit.t) : std::numeric_limits<float>::infinity();
            }
        }
    });
    return depth;
}

}  // namespace luxel::post
