// Entry point of weathergen_bench; the benchmarks register themselves from the other
// bench/*.cpp files (graph-driven ones at static initialisation, from graphs/*.json).
#include <benchmark/benchmark.h>

BENCHMARK_MAIN();
