// Images from the voxel renderer: samples per pixel, primary ray cones, and the sun visibility
// structures and the emissive faces' lists built once per image when the options ask for them.
#pragma once

#include "luxel/core/image.h"
#include "luxel/voxel/camera.h"
#include "luxel/voxel/shading.h"
#include "luxel/voxel/texture_set.h"
#include "luxel/voxel/voxel_world.h"

namespace luxel::voxel {

// Most samples per pixel (LUXEL_MAX_SAMPLES_PER_PIXEL in shared/pixel_samples.h).
inline constexpr int kMaxSamplesPerPixel = 256;

// The ray cone of a primary ray: zero width at the eye, spreading by one pixel's angle.
RayCone primaryCone(const Camera& camera);

// options.samplesPerPixel clamped to 1..kMaxSamplesPerPixel.
int samplesPerPixel(const ShadeOptions& options);

// The camera ray of sample k of n in pixel (px, py), at the stratified, per-pixel deterministic
// position of shared/pixel_samples.h (one sample: the pixel centre). The ray caster, sky
// visibility and the radiance cascades' picture all sample pixels so.
Ray pixelSampleRay(const Camera& camera, int px, int py, int k, int n);

// Radiance of pixel (px, py): options.samplesPerPixel samples at stratified, per-pixel
// deterministic positions (shared/pixel_samples.h; one sample: the pixel centre), averaged.
// Each sample's cone spreads by the pixel angle / sqrt(samples).
Rgb shadePixel(const VoxelWorld& world, const Camera& camera, int px, int py,
               const ShadeOptions& options, const TextureSet* textures = nullptr);

// A camera.width() x camera.height() RGB image, rows in parallel. With Physical lighting and no
// options.sunVisibility, builds the visibility structures options.shadowSettings ask for first,
// and with options.emitterLight and no options.emitterLights the emissive faces' lists
// (emitter_light.h).
Image render(const VoxelWorld& world, const Camera& camera, const ShadeOptions& options,
             const TextureSet* textures = nullptr);

}  // namespace luxel::voxel
