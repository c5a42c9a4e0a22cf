// Entry point of the benchmark harness.
#include <benchmark/benchmark.h>

BENCHMARK_MAIN();
