// The voxel path tracer's images (path_trace.h): per-pixel running sums of the samples, the mean
// radiance and its standard error.
#include <algorithm>
#include <cmath>
#include <limits>

#include "luxel/core/check.h"
#include "luxel/core/memory.h"
#include "luxel/core/parallel.h"
#include "luxel/voxel/path_trace.h"

namespace luxel::voxel {
namespace {

// The standard error of the mean of n samples with this sum and sum of squares (unbiased
// variance); 0 for a single sample.
double standardError(double sum, double sumSquares, int n) {
    if (n < 2) return 0.0;
    const double variance = std::max(0.0, (sumSquares - sum * sum / n) / (n - 1));
    return std::sqrt(variance / n);
}

}  // namespace

PathTracer::PathTracer(const VoxelWorld& world, const Camera& camera, const ShadeOptions& shading,
                       const PathTraceOptions& options, const TextureSet* textures)
    : world_(&world),
      camera_(camera),
      shading_(shading),
      options_(options),
      textures_(textures),
      emitters_(options.sampleEmitters ? PathEmitters::find(world, shading.materials)
                                       : PathEmitters{}),
      sums_(static_cast<std::size_t>(camera.width()) * camera.height()) {}

Status validatePathTrace(const ShadeOptions& shading, const PathTraceOptions& options,
                         const Camera& camera) {
    if (Status s = validatePathTrace(shading, options); !s) return s;
    if (std::int64_t(camera.width()) * camera.height() > kMaxPathPixels) {
        return Error("path tracing: image " + std::to_string(camera.width()) + "x" +
                     std::to_string(camera.height()) + " has more than " +
                     std::to_string(kMaxPathPixels) + " pixels");
    }
    return Ok{};
}

PathTraceMemory estimatePathTraceMemory(int width, int height) {
    PathTraceMemory m;
    m.host = std::uint64_t(std::max(width, 0)) * std::uint64_t(std::max(height, 0)) *
             sizeof(PathPixelSums);
    return m;
}

Result<PathTracer> PathTracer::create(const VoxelWorld& world, const Camera& camera,
                                      const ShadeOptions& shading, const PathTraceOptions& options,
                                      const TextureSet* textures) {
    if (Status s = validatePathTrace(shading, options, camera); !s) return s.error();
    if (Status s = checkMemory(estimatePathTraceMemory(camera.width(), camera.height()).host,
                               "path tracing " + std::to_string(camera.width()) + "x" +
                                   std::to_string(camera.height()) + " (the running sums)");
        !s) {
        return s.error();
    }
    return PathTracer(world, camera, shading, options, textures);
}

Status PathTracer::addSamples(int count) {
    if (count < 1 || count > kMaxPathSamples - samples_) {
        return Error("path tracing: " + std::to_string(count) + " more samples after " +
                     std::to_string(samples_) + " is outside 1.." +
                     std::to_string(kMaxPathSamples) + " in all");
    }
    const int width = camera_.width(), first = samples_;
    parallelForRange(camera_.height(), 1, [&](int begin, int end) {
        for (int y = begin; y < end; ++y) {
            for (int x = 0; x < width; ++x) {
                const std::uint64_t pixel = std::uint64_t(y) * width + x;
                PathPixelSums& sums = sums_[pixel];
                for (int k = first; k < first + count; ++k) {
                    PathRng rng(options_.seed, pixel, std::uint64_t(k));
                    const float jx = rng.next(), jy = rng.next();  // uniform in the pixel
                    const Ray ray = camera_.rayAt(x + double(jx), y + double(jy));
                    const Rgb c =
                        tracePath(*world_, textures_, ray, shading_, options_, rng, &emitters_);
                    sums.add(c);
                }
            }
        }
    });
    samples_ += count;
    return Ok{};
}

PathTraceImage PathTracer::image() const {
    return pathTraceImageOf(sums_, camera_.width(), camera_.height(), samples_);
}

PathTraceImage pathTraceImageOf(std::span<const PathPixelSums> sums, int width, int height,
                                int samples) {
    LUXEL_CHECK_EQ(sums.size(), static_cast<std::size_t>(width) * height);
    const int n = samples;
    PathTraceImage out;
    out.radiance = Image(width, height, 3);
    out.standardError = Image(width, height, 3);
    out.samplesPerPixel = n;
    double errorSum = 0.0, meanSum = 0.0;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const PathPixelSums& s = sums[std::size_t(y) * width + x];
            for (int i = 0; i < 3; ++i) {
                out.radiance.at(x, y, i) = n > 0 ? float(s.sum[i] / n) : 0.0f;
                out.standardError.at(x, y, i) = float(standardError(s.sum[i], s.sumSquares[i], n));
            }
            if (n > 0) meanSum += s.luminance / n;
            errorSum += standardError(s.luminance, s.luminanceSquares, n);
        }
    }
    out.relativeError =
        n >= 2 && meanSum > 0.0 ? errorSum / meanSum : std::numeric_limits<double>::quiet_NaN();
    return out;
}

Result<PathTraceImage> pathTrace(const VoxelWorld& world, const Camera& camera,
                                 const ShadeOptions& shading, const PathTraceOptions& options,
                                 const TextureSet* textures) {
    auto tracer = PathTracer::create(world, camera, shading, options, textures);
    if (!tracer) return tracer.error();
    if (Status s = tracer->addSamples(options.samplesPerPixel); !s) return s.error();
    return tracer->image();
}

}  // namespace luxel::voxel
