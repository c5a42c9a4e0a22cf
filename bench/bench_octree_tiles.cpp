// The WebGL octree design's tile rendering (luxel/octree/octree_tiles.h) against the exact
// traversal (renderOctree's surface mode), the same camera, CPU, no shadows (the primary
// visibility is what the design changes): time per frame, and the loss counters of the tiles
// (differ_pct: hit voxel not the exact one; missed_pct: surface lost) on a 256^3 CT-like phantom
// and the 4096^3 sparse terrain of scenes/octree/terrain.json (depth 12: the design's 4 passes of
// 8^3 tiles).
//   build/release/bench/luxel_bench --benchmark_filter=OctreeTiles
#include <benchmark/benchmark.h>

#include "luxel/octree/octree_build.h"
#include "luxel/octree/octree_render.h"
#include "luxel/octree/octree_tiles.h"
#include "luxel/octree/volume_generators.h"

namespace {

using namespace luxel;
using namespace luxel::octree;

struct Scene {
    Octree tree;
    voxel::Camera camera;
};

const Scene& phantom() {
    static const Scene s{*buildOctree(*makePhantom(256)),
                         *voxel::Camera::lookAt({420, 300, -220}, {128, 128, 128}, 40, 320, 240)};
    return s;
}

const Scene& terrain() {
    static const Scene s{
        *buildOctree(*makeSparseTerrain(4096, 3)),
        *voxel::Camera::lookAt({-300, 2600, -300}, {1400, 1400, 1400}, 50, 320, 180)};
    return s;
}

OctreeRenderOptions surface() {
    OctreeRenderOptions o;
    o.shadows = false;
    return o;
}

void exact(benchmark::State& state, const Scene& (*scene)()) {
    const Scene& s = scene();
    for (auto _ : state) benchmark::DoNotOptimize(renderOctree(s.tree, s.camera, surface()));
    state.counters["pixels"] = s.camera.width() * s.camera.height();
}

void tiles(benchmark::State& state, const Scene& (*scene)()) {
    const Scene& s = scene();
    Result<TileRender> last = Error("not run");
    for (auto _ : state) {
        last = renderOctreeTiles(s.tree, s.camera, surface());
        benchmark::DoNotOptimize(last);
    }
    const auto c = compareTiles(last->pixels, exactPixels(s.tree, s.camera, surface()));
    state.counters["differ_pct"] = c->differingPercent();
    state.counters["missed_pct"] = c->missedPercent();
    state.counters["dead_end_pct"] =
        100.0 * static_cast<double>(c->deadEnds) / static_cast<double>(c->pixels);
    state.counters["queries_per_px"] =
        static_cast<double>(c->samples) / static_cast<double>(c->pixels);
}

BENCHMARK_CAPTURE(exact, phantom256, &phantom)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(tiles, phantom256, &phantom)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(exact, terrain4096, &terrain)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(tiles, terrain4096, &terrain)->Unit(benchmark::kMillisecond);

}  // namespace
