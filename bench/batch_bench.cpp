// BM_Batch/<jobs>: 200 compiles with SPIR-V (the 7 bundled graphs, cycled) through
// compileBatch at 1 and 2 jobs. Static-switch variants do not exist yet, so each
// compile is one material with its own weather preset. The target
// is a >= 1.8x speed-up on 2 cores.
#include <benchmark/benchmark.h>

#include "bench/bench_common.hpp"
#include "compiler/batch_compile.hpp"

namespace {

constexpr std::size_t kCompiles = 200;

void batch(benchmark::State& state) {
  std::vector<std::string> graphs;
  for (std::size_t i = 0; graphs.size() < kCompiles; ++i) {
    const auto& all = wg::bench::bundledGraphs();
    graphs.push_back(all[i % all.size()].path);
  }
  wg::CompileOptions options;  // SPIR-V included, as a build step runs it
  for (auto _ : state) {
    auto results = wg::compileBatch(graphs, options, static_cast<int>(state.range(0)));
    benchmark::DoNotOptimize(results);
  }
  state.counters["compiles"] = static_cast<double>(kCompiles);
}

BENCHMARK(batch)->Name("BM_Batch")->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
