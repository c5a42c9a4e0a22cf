// A progressive Monte Carlo path tracer over the voxel world: the ground truth that faster voxel
// lighting is measured against (docs/algorithms/voxel-path-tracing.md).
//
// Surfaces have the scene's materials as the physical ray caster reads them (surface colour =
// voxel colour x texel x material albedo): a diffuse base under a Fresnel-weighted GGX or mirror
// layer, metals, and transmissive voxels that refract light in and out (total internal
// reflection, Beer-Lambert absorption inside); emissive materials emit their `emission`. Light
// comes from the sun (a disk of angular radius `sunAngularRadius` giving `sunIrradiance` on a
// face square to `sunDirection`, or a delta light when the radius is 0), the scene's gradient
// sky (skyColor in shading.h), which rays leaving the world see, and the emissive voxels; the
// sun and the emitters are sampled by next event estimation and combined with the bounce rays by
// multiple importance sampling. Russian roulette ends paths after `rouletteAfter` events. Each
// sample draws its random numbers from a counter-based generator keyed by (seed, pixel, sample),
// so images are bit-identical for any thread count and for any split of the samples into
// progressive passes.
#pragma once

#include <cstdint>
#include <vector>

#include "luxel/core/error.h"
#include "luxel/core/image.h"
#include "luxel/core/vec.h"
#include "luxel/voxel/camera.h"
#include "luxel/voxel/dda.h"
#include "luxel/voxel/path_trace_emitters.h"
#include "luxel/voxel/path_trace_rng.h"
#include "luxel/voxel/path_trace_sums.h"
#include "luxel/voxel/shading.h"
#include "luxel/voxel/texture_set.h"
#include "luxel/voxel/voxel_world.h"

namespace luxel::voxel {

inline constexpr int kMaxPathSamples = 1 << 20;  // samples per pixel
inline constexpr int kMaxPathBounces = 1024;
// Largest image: the accumulator keeps 8 doubles (64 bytes) per pixel.
inline constexpr std::int64_t kMaxPathPixels = std::int64_t(1) << 26;

struct PathTraceOptions {
    int samplesPerPixel = 16;  // 1..kMaxPathSamples (the standard error needs 2 or more)
    // Most surface reflections of the light that reaches the eye, 0..kMaxPathBounces: 0 shows
    // emitters and the sky only, 1 adds direct sun and sky light, 2 one bounce of indirect light.
    int maxBounces = 8;
    int rouletteAfter = 3;  // reflections before Russian roulette may end a path (>= 0)
    std::uint64_t seed = 1;
    // Next event estimation towards the emissive voxels, combined with the bounce rays by
    // multiple importance sampling; off: bounce rays alone find them (same mean, more noise).
    bool sampleEmitters = true;
    // Next event estimation towards the sun follows its shadow ray through glass and mirrors
    // (surfaces without a smooth lobe), so sunlight through a window converges like direct
    // light; off: only bounce rays find the sun behind them (same mean, fireflies). It applies
    // when shading.refraction is on and a material lets light through.
    bool sunThroughGlass = true;
};

// Memory the path tracer needs for an image, estimated before it allocates: PathTracer and
// PathTracerGpu refuse, with these numbers, what does not fit, and `luxel info` prints them.
struct PathTraceMemory {
    // Host: the running sums in double (PathPixelSums, 64 bytes a pixel), and on the GPU one
    // download of the float sums (48 bytes a pixel).
    std::uint64_t host = 0;
    // Device (GPU only): the world's upload (estimateVoxelGpuMemory without an image), the float
    // sums (48 bytes a pixel) and the emissive voxels (16 bytes each, at least one).
    std::uint64_t world = 0, sums = 0, emitters = 0;
    std::uint64_t device() const { return world + sums + emitters; }
};

// The CPU tracer's memory at width x height.
PathTraceMemory estimatePathTraceMemory(int width, int height);

// The options and the scene light (ShadeOptions' sun direction and irradiance, sky colours)
// checked: finite, in range, a non-zero sun direction; the error names the field.
Status validatePathTrace(const ShadeOptions& shading, const PathTraceOptions& options);
// The same, and an image of at most kMaxPathPixels pixels (both backends check this).
Status validatePathTrace(const ShadeOptions& shading, const PathTraceOptions& options,
                         const Camera& camera);

// Radiance carried by one path sample along `ray`, drawing its random numbers from `rng`.
// `shading` and `options` must be valid (validatePathTrace). `emitters` (PathEmitters::find of
// the world and shading.materials; null or empty: none) are sampled as lights.
Rgb tracePath(const VoxelWorld& world, const TextureSet* textures, const Ray& ray,
              const ShadeOptions& shading, const PathTraceOptions& options, PathRng& rng,
              const PathEmitters* emitters = nullptr);

// Per-pixel running sums of the samples (and of their squares), so a render can grow pass by
// pass: pass after pass gives the same image as one pass of all the samples. Keeps references to
// the world and the textures, which must outlive it.
class PathTracer {
  public:
    // Refuses, with the bytes, running sums that do not fit in memory (estimatePathTraceMemory).
    static Result<PathTracer> create(const VoxelWorld& world, const Camera& camera,
                                     const ShadeOptions& shading, const PathTraceOptions& options,
                                     const TextureSet* textures = nullptr);

    // Adds samples samplesDone() .. samplesDone() + count - 1 of every pixel (rows in parallel).
    // Fails when the total would exceed kMaxPathSamples.
    Status addSamples(int count);
    int samplesDone() const { return samples_; }
    PathTraceImage image() const;

  private:
    PathTracer(const VoxelWorld& world, const Camera& camera, const ShadeOptions& shading,
               const PathTraceOptions& options, const TextureSet* textures);

    const VoxelWorld* world_;
    Camera camera_;
    ShadeOptions shading_;
    PathTraceOptions options_;
    const TextureSet* textures_;
    PathEmitters emitters_;
    std::vector<PathPixelSums> sums_;
    int samples_ = 0;
};

// PathTracer with options.samplesPerPixel samples in one pass.
Result<PathTraceImage> pathTrace(const VoxelWorld& world, const Camera& camera,
                                 const ShadeOptions& shading, const PathTraceOptions& options,
                                 const TextureSet* textures = nullptr);

}  // namespace luxel::voxel
