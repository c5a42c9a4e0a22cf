// Rendering an octree to a linear RGB image (docs/algorithms/sparse-voxel-octree.md §5): the
// surface, volume and additive modes of one per-pixel kernel shared with the GPU
// (src/gpu/shaders/shared/octree_render.h). renderOctree is the CPU twin of OctreeGpu::render.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "luxel/core/error.h"
#include "luxel/core/image.h"
#include "luxel/core/vec.h"
#include "luxel/octree/octree.h"
#include "luxel/voxel/camera.h"

namespace luxel::octree {

struct OctreeLightCache;  // octree_light_cache.h

// OctreeRenderOptions::lightCacheStride: the smallest power of two giving at most this many cells
// per axis.
inline constexpr int kLightCacheAuto = -1;
inline constexpr int kLightCacheAutoCells = 128;

enum class OctreeMode {
    Surface,   // the first leaf at least `threshold`, lit by sky and sun, with shadows
    Volume,    // front-to-back compositing of the opacities, early termination
    Additive,  // the WebGL octree design's additive transparency: emission-like, no occlusion
    // The WebGL octree design's own proposal (octree_tiles.h): 8^3 tiles, fixed-step marching,
    // one scale per pass, shaded as the surface mode; lossy against the exact walk.
    Tiles,
};
Result<OctreeMode> parseOctreeMode(std::string_view text, std::string_view what = "mode");
const char* octreeModeName(OctreeMode mode);

struct OctreeRenderOptions {
    OctreeMode mode = OctreeMode::Surface;
    std::uint8_t threshold = 1;  // surface mode: the least opacity that is a surface (1..255)
    float opacityScale = 1.0f;   // opacity per voxel length = value / 255 * scale, capped at 1
    // The transfer window: values at or below the low end are clear, at or above the high end
    // full strength, linear between (then times opacityScale); 0..255 is value / 255.
    std::uint8_t windowLow = 0, windowHigh = 255;
    Vec3 sunDirection{0.45f, 0.8f, 0.35f};  // towards the sun (normalised when rendering)
    Rgb sun{2.2f, 2.1f, 1.9f};              // sun radiance scale
    Rgb sky{0.55f, 0.7f, 0.95f};            // sky light and background
    float ambient = 0.35f;                  // fraction of the sky that lights surfaces and media
    // Surface shadows: hard with sunRadiusDegrees 0 or one sample, else soft over the sun's cone.
    bool shadows = true;
    float sunRadiusDegrees = 0.0f;
    int shadowSamples = 1;
    // Volume mode: sunlight scattered in the medium (subsurface scattering in translucent
    // matter); off, the leaf colours are emitted and absorbed only.
    bool scattering = true;
    float albedo = 0.8f;  // scattering / extinction
    float phaseG = 0.3f;  // Henyey-Greenstein anisotropy, in (-1, 1)
    int octaves = 3;      // 1: single scattering only; more add multiple-scattering octaves
    // Weight ratio between successive octaves, in [0, 1]. 0.3 with 3 octaves matches Monte Carlo
    // path tracing within 12% (relative L1) on tests/octree/octree_scattering_test.cpp's sphere,
    // where single scattering alone is 43% dark.
    float octaveWeight = 0.3f;
    // Scattering reads the sun's transmittance from a cache at the corners of a grid of this
    // spacing in voxels (octree_light_cache.h): kLightCacheAuto, 0 = exact rays at every sample
    // (slow), or a spacing up to 4096.
    int lightCacheStride = kLightCacheAuto;
};

// Every option checked (NaN, out of range) with an Error naming it.
Status validateRenderOptions(const OctreeRenderOptions& options);

// `tree` must be valid; the image has the camera's size. With `lightCache`, a cache that matches
// the tree and options is reused and any other is refilled there (frames under one light fill
// it once); without, a cache is filled for this render alone.
Result<Image> renderOctree(const Octree& tree, const voxel::Camera& camera,
                           const OctreeRenderOptions& options,
                           OctreeLightCache* lightCache = nullptr);

}  // namespace luxel::octree
