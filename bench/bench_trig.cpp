// Taylor series against built-in sin/asin and minimax asin: accuracy (max error counters) and
// throughput on the CPU; the same kernels timed on the GPU with timestamps (on lavapipe that is
// the CPU emulation of a GPU). docs/algorithms/trig-approximations.md.
//   build/release/bench/luxel_bench --benchmark_filter=Trig
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <vector>

#include "gpu/shaders/shared/trig_approx.h"
#include "luxel/gpu/context.h"
#include "luxel/post/post_gpu.h"

namespace {

using namespace luxel;
namespace shared = luxel::gpu::shared;

constexpr double kPi = 3.14159265358979323846;

std::vector<float> grid(double lo, double hi, int n) {
    std::vector<float> x(n);
    for (int i = 0; i < n; ++i) x[i] = static_cast<float>(lo + (hi - lo) * (i + 0.5) / n);
    return x;
}

// Max |f(x) - reference(x)| over 100k points of [lo, hi], the reference in double.
template <typename F, typename R>
double maxError(F f, R reference, double lo, double hi) {
    double worst = 0;
    for (float x : grid(lo, hi, 100000)) {
        worst = std::max(worst, std::abs(double(f(x)) - reference(double(x))));
    }
    return worst;
}

template <typename F>
void throughput(benchmark::State& state, F f, double lo, double hi) {
    const std::vector<float> x = grid(lo, hi, 4096);
    for (auto _ : state) {
        float sum = 0;
        for (float v : x) sum += f(v);
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(x.size()));
}

void BM_TrigSin(benchmark::State& state) {
    const int terms = static_cast<int>(state.range(0));  // 0: std::sin
    // Constant term counts, so the compiler unrolls the series and folds its coefficients.
    const auto f = [terms](float x) {
        switch (terms) {
            case 3:
                return shared::taylorSin(x, 3);
            case 5:
                return shared::taylorSin(x, 5);
            case 7:
                return shared::taylorSin(x, 7);
            case 9:
                return shared::taylorSin(x, 9);
            default:
                return std::sin(x);
        }
    };
    const auto s = [](double x) { return std::sin(x); };
    state.counters["err_half_pi"] = maxError(f, s, -kPi / 2, kPi / 2);
    state.counters["err_pi"] = maxError(f, s, -kPi, kPi);
    throughput(state, f, -kPi / 2, kPi / 2);
}
BENCHMARK(BM_TrigSin)->Arg(0)->Arg(3)->Arg(5)->Arg(7)->Arg(9)->ArgName("terms");

// terms: 0 std::asin, > 0 Taylor with that many terms, -4 / -8 the minimax fits.
void BM_TrigAsin(benchmark::State& state) {
    const int terms = static_cast<int>(state.range(0));
    const auto f = [terms](float x) {
        switch (terms) {
            case -4:
                return shared::minimaxAsin4(x);
            case -8:
                return shared::minimaxAsin8(x);
            case 3:
                return shared::taylorAsin(x, 3);
            case 6:
                return shared::taylorAsin(x, 6);
            case 14:
                return shared::taylorAsin(x, 14);
            case 40:
                return shared::taylorAsin(x, 40);
            default:
                return std::asin(x);
        }
    };
    const auto a = [](double x) { return std::asin(x); };
    state.counters["err_0.5"] = maxError(f, a, -0.5, 0.5);
    state.counters["err_0.9"] = maxError(f, a, -0.9, 0.9);
    state.counters["err_0.99"] = maxError(f, a, -0.99, 0.99);
    state.counters["err_1"] = maxError(f, a, -1.0, 1.0);
    throughput(state, f, -1.0, 1.0);
}
BENCHMARK(BM_TrigAsin)
    ->Arg(0)
    ->Arg(3)
    ->Arg(6)
    ->Arg(14)
    ->Arg(40)
    ->Arg(-4)
    ->Arg(-8)
    ->ArgName("terms");

// GPU: 65536 inputs x 256 evaluations each, timed with GPU timestamps (manual time).
gpu::Context* benchGpu() {
    static std::unique_ptr<gpu::Context> context = [] {
        auto c = gpu::Context::create();
        return c ? std::move(*c) : nullptr;
    }();
    return context.get();
}

void BM_TrigGpu(benchmark::State& state) {
    gpu::Context* context = benchGpu();
    if (!context) {
        state.SkipWithError("no Vulkan device");
        return;
    }
    const auto function = static_cast<post::TrigFunction>(state.range(0));
    const int terms = static_cast<int>(state.range(1));
    const bool sine =
        function == post::TrigFunction::Sin || function == post::TrigFunction::TaylorSin;
    const std::vector<float> x = sine ? grid(-kPi / 2, kPi / 2, 65536) : grid(-1, 1, 65536);
    const int iterations = 256;
    for (auto _ : state) {
        auto run = post::trigGpu(*context, x, function, terms, iterations);
        if (!run) {
            state.SkipWithError(run.error().message().c_str());
            return;
        }
        state.SetIterationTime(run->milliseconds * 1e-3);
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(x.size()) * iterations);
    state.SetLabel(context->device().name);
}
BENCHMARK(BM_TrigGpu)
    ->Args({int(post::TrigFunction::Sin), 0})
    ->Args({int(post::TrigFunction::TaylorSin), 5})
    ->Args({int(post::TrigFunction::TaylorSin), 7})
    ->Args({int(post::TrigFunction::Asin), 0})
    ->Args({int(post::TrigFunction::TaylorAsin), 6})
    ->Args({int(post::TrigFunction::TaylorAsin), 14})
    ->Args({int(post::TrigFunction::MinimaxAsin), 0})
    ->ArgNames({"function", "terms"})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);

}  // namespace
