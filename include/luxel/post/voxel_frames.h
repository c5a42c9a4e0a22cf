// The post module's bridge to the voxel renderer (library luxel_post_voxel, which links
// luxel_voxel; luxel_post itself does not): cameras at another resolution, jittered frames and
// primary-hit depth for the temporal upscaler.
#pragma once

#include "luxel/core/image.h"
#include "luxel/post/pinhole_view.h"
#include "luxel/voxel/camera.h"
#include "luxel/voxel/shading.h"
#include "luxel/voxel/texture_set.h"
#include "luxel/voxel/voxel_world.h"

namespace luxel::post {

// The same camera (position, orientation, field of view) at another image size.
voxel::Camera resizedCamera(const voxel::Camera& camera, int width, int height);
PinholeView viewOf(const voxel::Camera& camera);

// Radiance through (x + 0.5 + jitter.x, y + 0.5 + jitter.y) for every pixel (one sample per
// pixel: temporal accumulation replaces options.samplesPerPixel). Builds the sun visibility that
// Physical lighting needs when options.sunVisibility is null, as voxel::render does.
Image renderJittered(const voxel::VoxelWorld& world, const voxel::Camera& camera,
                     const voxel::ShadeOptions& options, const voxel::TextureSet* textures,
                     Vec2d jitter);
// Distance to the first hit along the same unit rays (+inf where a ray reaches the sky); 1 channel.
Image primaryDepth(const voxel::VoxelWorld& world, const voxel::Camera& camera, Vec2d jitter);

}  // namespace luxel::post
