// Reference 2D solver throughput: rays per second on the shipped scenes.
//   build/release/bench/luxel_bench --benchmark_filter=Reference
#include <benchmark/benchmark.h>

#include <string>

#include "bench_scenes.h"
#include "luxel/gi2d/rasterize.h"
#include "luxel/gi2d/reference_solver.h"
#include "luxel/gi2d/scene2d_json.h"

namespace {

luxel::gi2d::Medium2D loadMedium(const std::string& name, int size) {
    const luxel::gi2d::Scene2D scene = luxel::bench::loadShipped2D(name);
    auto medium = luxel::gi2d::rasterize(scene, {size, size, 16});
    if (!medium) throw std::runtime_error(medium.error().message());
    return std::move(*medium);
}

void referenceSolve(benchmark::State& state, const std::string& scene) {
    const int size = static_cast<int>(state.range(0));
    const int rays = static_cast<int>(state.range(1));
    const auto medium = loadMedium(scene, size);
    luxel::gi2d::ReferenceOptions options;
    options.rays = rays;
    for (auto _ : state) {
        auto fluence = luxel::gi2d::solveReference(medium, options);
        benchmark::DoNotOptimize(fluence);
    }
    const double raysPerFrame = static_cast<double>(size) * size * rays;
    state.counters["rays/s"] =
        benchmark::Counter(raysPerFrame, benchmark::Counter::kIsIterationInvariantRate);
}

void rasterize(benchmark::State& state, const std::string& scene) {
    const int size = static_cast<int>(state.range(0));
    const luxel::gi2d::Scene2D loaded = luxel::bench::loadShipped2D(scene);
    for (auto _ : state) {
        auto medium = luxel::gi2d::rasterize(loaded, {size, size, 16});
        benchmark::DoNotOptimize(medium);
    }
}

}  // namespace

BENCHMARK_CAPTURE(referenceSolve, penumbra, "penumbra.json")
    ->Args({256, 256})
    ->Args({512, 256})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(referenceSolve, fog, "fog.json")
    ->Args({256, 256})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(referenceSolve, room, "room.json")
    ->Args({256, 256})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(rasterize, room, "room.json")
    ->Arg(512)
    ->Arg(2048)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
