// `luxel octree tiles SCENE [--size WxH] [--backend cpu|gpu] [--tile-bits N] [--shadows]`: the
// WebGL octree design's tile rendering (luxel/octree/octree_tiles.h) against the exact traversal on
// an octree scene: the pixels it loses (the loss table) and the time per frame of both, surface
// mode.
#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "commands/command.h"
#include "luxel/core/timer.h"
#include "luxel/gpu/context.h"
#include "luxel/octree/octree.h"
#include "luxel/octree/octree_gpu.h"
#include "luxel/octree/octree_render.h"
#include "luxel/octree/octree_tiles.h"
#include "luxel/octree/octree_tiles_gpu.h"

namespace luxel::cli {
namespace {

struct TilesArgs {
    std::string scene, size, backend = "cpu", device;
    int tileBits = 3, repeat = 3;
    bool shadows = false;
};

// The best of `repeat` runs of `frame` (which returns false on failure), in milliseconds. On the
// GPU `timings` collects the frame's dispatches: `bestDispatch` is the least sum of their times
// (the device's own work, without uploads and read-backs).
template <typename Frame>
Result<double> bestOf(int repeat, Frame&& frame, std::vector<gpu::PassTiming>* timings = nullptr,
                      double* bestDispatch = nullptr) {
    double best = 1e300;
    for (int i = 0; i < repeat; ++i) {
        if (timings) timings->clear();
        Stopwatch clock;
        if (Status s = frame(); !s) return s.error();
        best = std::min(best, clock.milliseconds());
        if (timings && bestDispatch) {
            double sum = 0;
            for (const gpu::PassTiming& t : *timings) sum += t.milliseconds;
            *bestDispatch = i == 0 ? sum : std::min(*bestDispatch, sum);
        }
    }
    return best;
}

void printRow(const char* what, long long count, long long of) {
    std::printf("  %-34s %9lld  %6.2f%%\n", what, count, of > 0 ? 100.0 * count / of : 0.0);
}

int runTiles(const TilesArgs& args) {
    auto backend = parseBenchBackend(args.backend);
    if (!backend) return reportError(backend.error());
    auto file = loadScene(args.scene, args.size);
    if (!file) return reportError(file.error());
    if (file->kind() != scene::SceneKind::Octree) {
        return reportError(Error(args.scene + ": " + sceneKindPhrase(file->kind()) +
                                 "; octree tiles works on octree scenes"));
    }
    const scene::OctreeScene& scene = file->octree();
    octree::OctreeRenderOptions options = scene.render;
    options.mode = octree::OctreeMode::Surface;  // the tiles find surfaces
    // Off by default: the design changes primary visibility, and shadows (traced exactly by both)
    // would cost the exact frame for the pixels the tiles lose.
    options.shadows = options.shadows && args.shadows;
    const octree::TileOptions tiles{.tileBits = args.tileBits};
    if (Status s = octree::validateTileOptions(tiles); !s) return reportError(s.error());
    const voxel::Camera& camera = scene.camera;

    std::unique_ptr<gpu::Context> context;
    if (*backend == gpu::Backend::Gpu) {
        auto opened = openBenchGpu(args.device);
        if (!opened) return reportError(opened.error());
        context = std::move(*opened);
    }
    Result<octree::TileRender> result = Error("no render");
    Result<double> exactMs = 0.0, tilesMs = 0.0;
    double exactDispatchMs = 0, tilesDispatchMs = 0;
    std::vector<gpu::PassTiming> timings;
    if (context) {
        auto exactGpu = octree::OctreeGpu::create(*context, scene.tree);
        if (!exactGpu) return reportError(exactGpu.error());
        auto tilesGpu = octree::OctreeTilesGpu::create(*context, scene.tree);
        if (!tilesGpu) return reportError(tilesGpu.error());
        exactMs = bestOf(
            args.repeat,
            [&]() -> Status {
                auto image = exactGpu->render(camera, options, &timings);
                return image ? Status(Ok{}) : Status(image.error());
            },
            &timings, &exactDispatchMs);
        tilesMs = bestOf(
            args.repeat,
            [&]() -> Status {
                result = tilesGpu->render(camera, options, tiles, &timings);
                return result ? Status(Ok{}) : Status(result.error());
            },
            &timings, &tilesDispatchMs);
    } else {
        exactMs = bestOf(args.repeat, [&]() -> Status {
            auto image = octree::renderOctree(scene.tree, camera, options);
            return image ? Status(Ok{}) : Status(image.error());
        });
        tilesMs = bestOf(args.repeat, [&]() -> Status {
            result = octree::renderOctreeTiles(scene.tree, camera, options, tiles);
            return result ? Status(Ok{}) : Status(result.error());
        });
    }
    if (!exactMs) return reportError(exactMs.error());
    if (!tilesMs) return reportError(tilesMs.error());
    if (!result) return reportError(result.error());
    auto c = octree::compareTiles(result->pixels, octree::exactPixels(scene.tree, camera, options));
    if (!c) return reportError(c.error());

    const int passes = octree::tilePassCount(scene.tree.depth, args.tileBits);
    std::printf("%s: octree (%s), depth %d, image %dx%d, %s\n", args.scene.c_str(),
                scene.source.c_str(), scene.tree.depth, camera.width(), camera.height(),
                context ? ("gpu: " + context->device().name).c_str() : "cpu");
    std::printf("  tiles of %d^3 cells, %d passes, threshold %d, surface mode, shadows %s\n",
                1 << args.tileBits, passes, options.threshold, options.shadows ? "on" : "off");
    std::printf("  %-34s %9s  %7s\n", "pixels", "count", "share");
    printRow("exact traversal hits a surface", c->exactHits, c->pixels);
    printRow("tiles hit the same voxel", c->sameVoxel, c->pixels);
    printRow("tiles hit a different voxel", c->differentVoxel, c->pixels);
    printRow("tiles miss a surface (lost)", c->missedSurface, c->pixels);
    printRow("  of which dead ends", c->deadEnds, c->pixels);
    printRow("tiles hit where exact misses", c->falseHit, c->pixels);
    std::printf("  hit voxel differs from exact      %9s  %6.2f%%\n", "", c->differingPercent());
    std::printf("  point queries per pixel (tiles)   %9.2f\n",
                static_cast<double>(c->samples) / static_cast<double>(c->pixels));
    std::printf("  frame, exact traversal            %9.3f ms\n", *exactMs);
    std::printf("  frame, tiles (%d passes)           %9.3f ms\n", passes, *tilesMs);
    if (context) {
        std::printf("  GPU dispatch, exact traversal     %9.3f ms\n", exactDispatchMs);
        std::printf("  GPU dispatch, tiles (%d passes)    %9.3f ms\n", passes, tilesDispatchMs);
    }
    return 0;
}

}  // namespace

// `luxel octree tiles`: registered by addOctreeCommand (octree.cpp).
CLI::App* addOctreeTilesCommand(CLI::App& octree, Runner& run) {
    auto args = std::make_shared<TilesArgs>();
    CLI::App* tiles = octree.add_subcommand(
        "tiles", "the WebGL octree design's tile rendering against the exact traversal");
    tiles->add_option("scene", args->scene, "octree scene (.json)")->required();
    tiles->add_option("--size", args->size, "image size WxH (default: the scene's camera)");
    tiles->add_option("--backend", args->backend, "cpu or gpu")->capture_default_str();
    tiles->add_option("--device", args->device, "GPU device (index or name part)");
    tiles->add_option("--tile-bits", args->tileBits, "tiles are 2^bits cells a side")
        ->check(wholeIn(1, octree::kMaxDepth))
        ->capture_default_str();
    tiles->add_flag("--shadows", args->shadows, "keep the scene's sun shadows in both frames");
    tiles->add_option("--repeat", args->repeat, "frames timed (the best is reported)")
        ->check(CLI::Range(1, 100))
        ->capture_default_str();
    run = [args] { return runTiles(*args); };
    return tiles;
}

}  // namespace luxel::cli
