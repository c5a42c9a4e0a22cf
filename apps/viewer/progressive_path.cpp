// Voxel mode's progressive path tracing (progressive_path.h).
#include "progressive_path.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "luxel/core/check.h"
#include "luxel/core/memory.h"
#include "luxel/core/timer.h"

namespace luxel::viewer {

int nextPathSamples(int done, int target, int lastCount, double lastMilliseconds,
                    double budgetMilliseconds) {
    const int left = std::max(0, target - done);
    if (left == 0) return 0;
    if (lastCount <= 0 || !(lastMilliseconds > 0.0) || !std::isfinite(lastMilliseconds)) return 1;
    const double perSample = lastMilliseconds / lastCount;
    const double fits = std::floor(budgetMilliseconds / perSample);
    const double most = std::min<double>(2.0 * lastCount, left);
    return static_cast<int>(std::clamp(fits, 1.0, most));
}

Status ProgressivePath::restart(const voxel::VoxelWorld& world, const voxel::Camera& camera,
                                const voxel::ShadeOptions& shading,
                                const voxel::PathTraceOptions& options,
                                const voxel::TextureSet* textures, int target, GpuWorld gpu) {
    clear();
    if (target < 1 || target > voxel::kMaxPathSamples) {
        return Error("path tracing: target " + std::to_string(target) +
                     " samples per pixel is outside 1.." + std::to_string(voxel::kMaxPathSamples));
    }
    // The running sums (8 doubles a pixel) and the mean and standard error images read back
    // every frame (6 floats a pixel).
    const std::uint64_t pixels = std::uint64_t(camera.width()) * std::uint64_t(camera.height());
    if (Status s =
            checkMemory(pixels * (64 + 24), "path tracing " + std::to_string(camera.width()) + "x" +
                                                std::to_string(camera.height()));
        !s) {
        return s;
    }
    if (gpu.context && gpu.renderer) {
        // The last view's tracer over the same upload starts over without sending the world.
        if (gpuTracer_ && &gpuTracer_->uploaded() == gpu.renderer && gpuWorld_ == &world) {
            if (Status s = gpuTracer_->restart(camera, shading, options); !s) return s;
        } else {
            gpuTracer_.reset();
            auto tracer = voxel::PathTracerGpu::create(*gpu.context, *gpu.renderer, world, camera,
                                                       shading, options);
            if (!tracer) return tracer.error();
            gpuTracer_.emplace(std::move(*tracer));
            gpuWorld_ = &world;
        }
        gpuActive_ = true;
    } else {
        gpuTracer_.reset();  // its device may go away: keep nothing of it
        auto tracer = voxel::PathTracer::create(world, camera, shading, options, textures);
        if (!tracer) return tracer.error();
        tracer_.emplace(std::move(*tracer));
    }
    target_ = target;
    return Ok{};
}

void ProgressivePath::clear() {
    tracer_.reset();
    gpuActive_ = false;
    lastCount_ = 0;
    added_ = 0;
    lastMilliseconds_ = 0.0;
}

void ProgressivePath::release() {
    clear();
    gpuTracer_.reset();
    gpuWorld_ = nullptr;
}

void ProgressivePath::setTarget(int target) {
    target_ = std::clamp(target, 1, voxel::kMaxPathSamples);
}

Result<voxel::PathTraceImage> ProgressivePath::step(double budgetMilliseconds) {
    LUXEL_CHECK(active());
    const int count =
        nextPathSamples(samples(), target_, lastCount_, lastMilliseconds_, budgetMilliseconds);
    added_ = count;
    if (count > 0) {
        Stopwatch clock;
        if (Status s = tracer_ ? tracer_->addSamples(count) : gpuTracer_->addSamples(count); !s) {
            return s.error();
        }
        lastMilliseconds_ = clock.milliseconds();
    }
    // A step that only reads the mean back keeps the timing of the last one that sampled.
    if (count > 0) lastCount_ = count;
    return tracer_ ? tracer_->image() : gpuTracer_->image();
}

}  // namespace luxel::viewer
