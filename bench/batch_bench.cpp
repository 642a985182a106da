// BM_Batch/<jobs>: 200 material x variant compiles with SPIR-V through compileBatch
// at 1 and 2 jobs: every static-switch variant of every bundled graph (as
// `--variants all` enumerates them), cycled. The target is a >= 1.8x speed-up
// on 2 cores.
#include <benchmark/benchmark.h>

#include "bench/bench_common.hpp"
#include "driver/batch_compile.hpp"

namespace {

constexpr std::size_t kCompiles = 200;

// Every variant of every bundled graph, in --variants all order.
std::vector<wg::CompileJob> everyVariant() {
  std::vector<wg::CompileJob> jobs;
  wg::VariantSelection all;
  all.all = true;
  for (const auto& g : wg::bench::bundledGraphs()) {
    std::string error;
    for (auto& v : wg::enumerateVariants(wg::declaredSwitchesOf(g.path), all, error))
      jobs.push_back({g.path, std::move(v)});
  }
  return jobs;
}

void batch(benchmark::State& state) {
  const std::vector<wg::CompileJob> variants = everyVariant();
  std::vector<wg::CompileJob> graphs;
  for (std::size_t i = 0; graphs.size() < kCompiles; ++i) graphs.push_back(variants[i % variants.size()]);
  wg::CompileOptions options;  // SPIR-V included, as a build step runs it
  for (auto _ : state) {
    auto results = wg::compileBatch(graphs, options, static_cast<int>(state.range(0)));
    benchmark::DoNotOptimize(results);
  }
  state.counters["compiles"] = static_cast<double>(kCompiles);
  state.counters["distinctVariants"] = static_cast<double>(variants.size());
}

BENCHMARK(batch)->Name("BM_Batch")->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
