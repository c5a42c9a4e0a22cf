// HRC and RC speed on the default scene: ms per frame, Mpixel/s, peak memory, and the error
// against a cached reference render where one exists (out/reference-cache/room_WxH.exr; `make demo`
// writes the 512x512 one).
//   build/release/bench/luxel_bench --benchmark_filter='hrc|rc'
//   LUXEL_BENCH_LARGE=1 build/release/bench/luxel_bench --benchmark_filter=hrc   (adds 4096, 8192;
//   RC: 4096)
//   LUXEL_THREADS=1 build/release/bench/luxel_bench --benchmark_filter=rc   (worker threads capped)
#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "bench_scenes.h"
#include "luxel/core/image_io.h"
#include "luxel/core/metrics.h"
#include "luxel/core/parallel.h"
#include "luxel/gi2d/hrc_solver.h"
#include "luxel/gi2d/rasterize.h"
#include "luxel/gi2d/rc_solver.h"
#include "luxel/gi2d/scene2d_json.h"

namespace {

double peakRssMiB() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<double>(usage.ru_maxrss) / 1024.0;  // ru_maxrss is in KiB on Linux
}

enum class Solver { Hrc, RcVanilla, RcFix };

luxel::Result<luxel::Image> solve(Solver solver, const luxel::gi2d::Medium2D& medium) {
    if (solver == Solver::Hrc) return luxel::gi2d::solveHrc(medium);
    luxel::gi2d::RcOptions options;
    options.merge =
        solver == Solver::RcFix ? luxel::gi2d::RcMerge::BilinearFix : luxel::gi2d::RcMerge::Vanilla;
    return luxel::gi2d::solveRc(medium, options);
}

std::uint64_t memoryEstimate(Solver solver, int size) {
    if (solver == Solver::Hrc) return luxel::gi2d::estimateHrcMemory(size, size).total();
    return luxel::gi2d::estimateRcMemory(size, size, {});
}

// LUXEL_THREADS=n caps the solvers' worker threads (unset or 0: all hardware threads).
int threadsFromEnvironment() {
    const char* threads = std::getenv("LUXEL_THREADS");
    return threads != nullptr ? std::atoi(threads) : 0;
}

void defaultScene(benchmark::State& state, Solver solver) {
    const luxel::ThreadLimit threads(threadsFromEnvironment());
    const int size = static_cast<int>(state.range(0));
    const luxel::gi2d::Scene2D scene = luxel::bench::loadShipped2D("room.json");
    auto medium = luxel::gi2d::rasterize(scene, {size, size, 16});
    if (!medium) throw std::runtime_error(medium.error().message());
    luxel::Image fluence;
    for (auto _ : state) {
        auto result = solve(solver, *medium);
        if (!result) {
            state.SkipWithError(result.error().message().c_str());
            return;
        }
        fluence = std::move(*result);
    }
    const double pixels = static_cast<double>(size) * size;
    state.counters["Mpixel/s"] =
        benchmark::Counter(pixels * 1e-6, benchmark::Counter::kIsIterationInvariantRate);
    state.counters["peak_MiB"] = peakRssMiB();
    state.counters["estimate_MiB"] = static_cast<double>(memoryEstimate(solver, size)) / (1 << 20);
    const std::string cached = std::string(LUXEL_SOURCE_DIR) + "/out/reference-cache/room_" +
                               std::to_string(size) + "x" + std::to_string(size) + ".exr";
    if (std::filesystem::exists(cached)) {
        if (auto reference = luxel::readExr(cached)) {
            if (auto e = luxel::compareImages(fluence, *reference)) {
                state.counters["relL1_vs_ref"] = e->relativeL1;
                state.counters["rmse_vs_ref"] = e->rmse / e->meanReference;
            }
        }
    }
}

void hrcSizes(benchmark::internal::Benchmark* b) {
    for (int size : {256, 512, 1024, 2048}) b->Arg(size);
    if (std::getenv("LUXEL_BENCH_LARGE") != nullptr) b->Arg(4096)->Arg(8192);
}

}  // namespace

void rcSizes(benchmark::internal::Benchmark* b) {
    for (int size : {256, 512, 1024, 2048}) b->Arg(size);
    if (std::getenv("LUXEL_BENCH_LARGE") != nullptr) b->Arg(4096);
}

BENCHMARK_CAPTURE(defaultScene, hrc, Solver::Hrc)
    ->Name("hrc/room")
    ->Apply(hrcSizes)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MeasureProcessCPUTime();
BENCHMARK_CAPTURE(defaultScene, rcVanilla, Solver::RcVanilla)
    ->Name("rc-vanilla/room")
    ->Apply(rcSizes)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MeasureProcessCPUTime();
BENCHMARK_CAPTURE(defaultScene, rcFix, Solver::RcFix)
    ->Name("rc-bilinear-fix/room")
    ->Apply(rcSizes)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MeasureProcessCPUTime();
