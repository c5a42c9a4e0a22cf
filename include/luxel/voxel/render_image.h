// Images from the voxel renderer: samples per pixel, primary ray cones, and the sun visibility
// structures and the emissive faces' lists built once per image when the options ask for them.
#pragma once

#include <optional>

#include "luxel/core/image.h"
#include "luxel/voxel/camera.h"
#include "luxel/voxel/emitter_light.h"
#include "luxel/voxel/shading.h"
#include "luxel/voxel/shadows/sun_visibility.h"
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

// `options` with what an image of them needs built once before its rays, where they ask for it
// and do not give it: with Physical lighting and no options.sunVisibility, the visibility
// structures options.shadowSettings ask for; with options.emitterLight and no
// options.emitterLights, the emissive faces' lists (emitter_light.h). options() points into what
// it holds, so it is neither copied nor moved.
class PreparedShading {
  public:
    PreparedShading(const VoxelWorld& world, const TextureSet* textures,
                    const ShadeOptions& options);
    PreparedShading(const PreparedShading&) = delete;
    PreparedShading& operator=(const PreparedShading&) = delete;

    const ShadeOptions& options() const { return options_; }

  private:
    ShadeOptions options_;
    std::optional<SunVisibility> visibility_;
    std::optional<EmitterLights> emitters_;
};

// A camera.width() x camera.height() RGB image, rows in parallel, of PreparedShading's options.
Image render(const VoxelWorld& world, const Camera& camera, const ShadeOptions& options,
             const TextureSet* textures = nullptr);

}  // namespace luxel::voxel
