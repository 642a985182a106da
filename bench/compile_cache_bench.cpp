// BM_EndToEnd/<graph>: one material as `weathergen compile` makes it by default, read
// from its file: GLSL and HLSL for both stages, each compiled to validated SPIR-V, and
// the reflection JSON. BM_CacheHit/<graph>: the same through a warm CompileCache, which
// reads the entry and checks every input file's digest instead.
// BM_EndToEndStageThreads/<graph>: BM_EndToEnd with a thread per stage, up to the cores.
#include <benchmark/benchmark.h>

#include <unistd.h>

#include <algorithm>
#include <thread>

#include "bench/bench_common.hpp"
#include "driver/compile_cache.hpp"

namespace {

void endToEnd(benchmark::State& state, const wg::bench::BundledGraph& graph, int stageThreads) {
  wg::CompileOptions options;
  options.stageThreads = stageThreads;
  for (auto _ : state) {
    auto result = wg::compileMaterialFile(graph.path, options);
    if (!result.material) state.SkipWithError(("does not compile: " + graph.path).c_str());
    benchmark::DoNotOptimize(result);
  }
}

// A cache directory of its own, removed with it.
struct ScratchDirectory {
  std::filesystem::path path = std::filesystem::temp_directory_path() /
                               ("weathergen-cache-bench-" + std::to_string(::getpid()));
  ~ScratchDirectory() {
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
  }
};

void cacheHit(benchmark::State& state, const wg::bench::BundledGraph& graph) {
  ScratchDirectory scratch;
  const wg::CompileCache cache(scratch.path);
  if (std::string problem = cache.prepare(); !problem.empty()) {
    state.SkipWithError(problem.c_str());
    return;
  }
  const wg::CompileOptions options;
  cache.compileFile(graph.path, options);  // the cold compile that stores the entry
  for (auto _ : state) {
    auto result = cache.compileFile(graph.path, options);
    if (!result.material || !result.material->ir.nodes.empty()) state.SkipWithError("not a cache hit");
    benchmark::DoNotOptimize(result);
  }
}

const bool registered = [] {
  for (const auto& graph : wg::bench::bundledGraphs()) {
    benchmark::RegisterBenchmark(("BM_EndToEnd/" + graph.stem).c_str(), endToEnd, graph, 1)->Unit(benchmark::kMillisecond);
    // The same with a thread per stage, up to the cores: wall time, as the threads share the work.
    const int cores = static_cast<int>(std::clamp(std::thread::hardware_concurrency(), 1u, 4u));
    benchmark::RegisterBenchmark(("BM_EndToEndStageThreads/" + graph.stem).c_str(), endToEnd, graph, cores)
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
    benchmark::RegisterBenchmark(("BM_CacheHit/" + graph.stem).c_str(), cacheHit, graph)->Unit(benchmark::kMicrosecond);
  }
  return true;
}();

}  // namespace
