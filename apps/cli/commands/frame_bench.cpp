// The frame table `luxel bench` prints for voxel and octree scenes (command.h: benchFrames).
#include <cstdio>
#include <string>
#include <vector>

#include "commands/command.h"
#include "commands/render_memory.h"
#include "luxel/core/image_size.h"
#include "luxel/core/timer.h"

namespace luxel::cli {

Result<std::vector<ImageSize>> benchSizes(const VoxelBenchRequest& request,
                                          const voxel::Camera& camera) {
    if (request.repeat < 1) return Error("--repeat must be at least 1");
    if (request.sizes.empty()) return std::vector<ImageSize>{{camera.width(), camera.height()}};
    return parseImageSizeList(request.sizes, "--sizes");
}

int benchFrames(const VoxelBenchRequest& request, const std::vector<ImageSize>& sizes,
                const voxel::Camera& camera, bool onGpu, const BenchFrame& frame) {
    std::printf("%11s %10s %9s%s\n", "size", "ms", "Mpix/s", onGpu ? "  dispatch ms" : "");
    for (const auto& [width, height] : sizes) {
        // The scene's view at this image size.
        auto sized = voxel::Camera::lookAt(camera.position(), camera.position() + camera.forward(),
                                           camera.fovYDegrees(), width, height);
        if (!sized) return reportError(sized.error());
        if (Status s = checkRenderMemory(width, height,
                                         frameBytes(width, height, post::PostOptions{}, onGpu));
            !s) {
            return reportError(s.error());
        }
        double best = 1e300, bestDispatch = 0;
        for (int r = 0; r < request.repeat + (onGpu ? 1 : 0); ++r) {  // GPU: one warm-up run
            std::vector<gpu::PassTiming> timings;
            Stopwatch clock;
            const Status rendered = frame(*sized, onGpu ? &timings : nullptr);
            const double ms = clock.milliseconds();
            if (!rendered) return reportError(rendered.error());
            if (onGpu && r == 0) continue;
            if (ms < best) {
                best = ms;
                // Every dispatch of the frame (the octree tiles mode runs one per scale), not the
                // transfers; a light cache kept from the warm-up frame is not refilled.
                bestDispatch = 0;
                for (const gpu::PassTiming& t : timings) {
                    if (t.name.find("upload") == std::string::npos &&
                        t.name.find("download") == std::string::npos) {
                        bestDispatch += t.milliseconds;
                    }
                }
            }
        }
        const std::string label = std::to_string(width) + "x" + std::to_string(height);
        std::printf("%11s %10.2f %9.2f", label.c_str(), best,
                    static_cast<double>(width) * height / best * 1e-3);
        if (onGpu) std::printf("  %11.2f", bestDispatch);
        std::printf("\n");
    }
    return 0;
}

}  // namespace luxel::cli
