// `luxel bench`: HRC frame times over canvas sizes, on the CPU or the GPU, with the GPU passes
// (timestamp queries) summed by kind. Voxel scenes go to bench_voxel.cpp.
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <map>
#include <memory>
#include <sstream>
#include <vector>

#include "commands/command.h"
#include "luxel/core/image_size.h"
#include "luxel/core/memory.h"
#include "luxel/core/parallel.h"
#include "luxel/core/timer.h"
#include "luxel/gi2d/hrc_solver.h"
#include "luxel/gi2d/rasterize.h"
#include "luxel/gpu/context.h"
#include "luxel/voxel/voxel_scene.h"

namespace luxel::cli {
namespace {

struct BenchArgs {
    std::string scene = "scenes/2d/room.json", backend = "cpu", device, sizes;
    int repeat = 3;
    int threads = 0;
    bool noDirectLight = false;
};

// "merge R3 f0" -> "merge"
std::string passKind(const std::string& name) {
    return name.substr(0, name.find(' '));
}

// memcpy bandwidth (bytes read + written per second) of one thread copying 128 MiB, best of 3.
double measureCopyBandwidth() {
    const std::size_t bytes = std::size_t{128} << 20;
    std::vector<char> from(bytes, 1), to(bytes, 0);
    double best = 1e300;
    for (int r = 0; r < 3; ++r) {
        Stopwatch clock;
        std::memcpy(to.data(), from.data(), bytes);
        best = std::min(best, clock.milliseconds());
    }
    return 2.0 * static_cast<double>(bytes) / best * 1e-6;
}

int runBench(const BenchArgs& args) {
    const ThreadLimit limit(args.threads);
    auto file = loadScene(args.scene, "");
    if (!file) return reportError(file.error());
    auto backend = parseBenchBackend(args.backend);
    if (!backend) return reportError(backend.error());
    if (file->kind() == scene::SceneKind::Octree) {
        return benchOctreeScene({args.scene, *backend, args.device, args.sizes, args.repeat},
                                std::move(file->octree()));
    }
    if (file->kind() == scene::SceneKind::Voxel) {
        return benchVoxelScene({args.scene, *backend, args.device, args.sizes, args.repeat},
                               std::move(file->voxel()));
    }
    auto sizes =
        parseImageSizeList(args.sizes.empty() ? "256,512,1024,2048" : args.sizes, "--sizes");
    if (!sizes) return reportError(sizes.error());
    auto sized = sizeScene(std::move(file->twoD()), "");
    if (!sized) return reportError(sized.error());
    std::unique_ptr<gpu::Context> context;
    if (*backend == gpu::Backend::Gpu) {
        auto opened = openBenchGpu(args.device);
        if (!opened) return reportError(opened.error());
        context = std::move(*opened);
    }
    std::printf("%s, hrc on the %s, best of %d\n", args.scene.c_str(), gpu::backendName(*backend),
                args.repeat);
    std::printf("%9s %10s %9s", "size", "ms", "Mpix/s");
    // "near": the exact near field of HRC §12.3, 0 where the medium does not bound the rays.
    // "direct": the compact lights' exact direct light of §12.5 (made on the CPU for both).
    const char* kinds[] = {"trace", "extend", "merge",  "readout", "finish",
                           "near",  "direct", "upload", "download"};
    const int kindCount = context ? 9 : 7;
    for (int k = 0; k < kindCount; ++k) std::printf(" %9s", kinds[k]);
    if (!context) std::printf(" %9s", "GB/s");
    std::printf("\n");
    for (const ImageSize& size : *sizes) {
        const int w = size.width, h = size.height;
        sized->width = w;
        sized->height = h;
        const std::string label = std::to_string(w) + "x" + std::to_string(h);
        const std::uint64_t needed =
            gi2d::mediumBytes(w, h) +
            (context ? gi2d::mediumBytes(w, h) : gi2d::estimateHrcMemory(w, h).total());
        if (Status s = checkMemory(needed, label); !s) {
            std::printf("%9s skipped: %s\n", label.c_str(), s.error().message().c_str());
            continue;
        }
        auto medium = rasterizeSized(*sized, args.scene, 16);
        if (!medium) return reportError(medium.error());
        double best = 1e300;
        std::map<std::string, double> bestPasses;
        std::uint64_t bestBytes = 0;
        for (int r = 0; r < args.repeat + (context ? 1 : 0); ++r) {  // GPU: one warm-up run
            std::vector<gpu::PassTiming> timings;
            std::vector<gi2d::HrcCpuPass> cpuPasses;
            Stopwatch clock;
            gi2d::HrcOptions options;
            options.exactDirectLight = !args.noDirectLight;
            auto result = context ? gi2d::solveHrcOnGpu(*context, *medium, options, &timings)
                                  : gi2d::solveHrc(*medium, options, &cpuPasses);
            const double ms = clock.milliseconds();
            if (!result) {
                std::printf("%9s failed: %s\n", label.c_str(), result.error().message().c_str());
                break;
            }
            if (context && r == 0) continue;
            if (ms < best) {
                best = ms;
                bestPasses.clear();
                for (const gpu::PassTiming& t : timings)
                    bestPasses[passKind(t.name)] += t.milliseconds;
                bestBytes = 0;
                for (const gi2d::HrcCpuPass& p : cpuPasses) {
                    bestPasses[passKind(p.name)] += p.milliseconds;
                    bestBytes += p.bytes;
                }
            }
        }
        if (best == 1e300) continue;
        std::printf("%9s %10.2f %9.2f", label.c_str(), best,
                    static_cast<double>(w) * h / best * 1e-3);
        for (int k = 0; k < kindCount; ++k) std::printf(" %9.2f", bestPasses[kinds[k]]);
        if (!context) std::printf(" %9.2f", static_cast<double>(bestBytes) / best * 1e-6);
        std::printf("\n");
    }
    if (context) {
        std::printf(
            "pass columns: GPU time (timestamps) summed over the 4 frustums; near: the exact "
            "near field where the medium bounds the rays; direct: the compact lights' direct "
            "light (CPU); upload and download are CPU-side copies\n");
    } else {
        std::printf(
            "pass columns: wall ms on the calling thread summed over the 4 frustums (waits for "
            "the other threads included); near: the exact near field where the medium bounds "
            "the rays; direct: the compact lights' direct light; GB/s: bytes of intervals, cones, "
            "medium and images "
            "the passes read and write, per second of the whole solve; memcpy on this machine: "
            "%.1f GB/s (one thread copying 128 MiB)\n",
            measureCopyBandwidth());
    }
    return 0;
}

}  // namespace

Runner addBenchCommand(CLI::App& app) {
    auto args = std::make_shared<BenchArgs>();
    app.add_option("scene", args->scene, "scene file (default: the default scene)")
        ->capture_default_str();
    app.add_option("--backend", args->backend, "cpu or gpu")->capture_default_str();
    app.add_option("--device", args->device, "GPU: device index or part of its name");
    app.add_option("--sizes", args->sizes,
                   "comma-separated sizes, WxH or N for NxN (default: 2D 256,512,1024,2048; "
                   "voxel the scene's camera size)");
    app.add_option("--repeat", args->repeat, "runs per size (the best is printed)")
        ->check(wholeIn(1, 1000))
        ->capture_default_str();
    app.add_option("--threads", args->threads, "CPU worker threads (0 = all cores)")
        ->check(wholeIn(0, 4096))
        ->capture_default_str();
    app.add_flag("--no-direct-light", args->noDirectLight,
                 "HRC: let the cascades carry the compact lights' direct light too");
    return [args] { return runBench(*args); };
}

}  // namespace luxel::cli
