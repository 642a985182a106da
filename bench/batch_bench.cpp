// BM_Batch/<jobs>: 200 material x variant compiles with SPIR-V through compileBatch
// at 1 and 2 jobs: every static-switch variant of every bundled graph (as
// `--variants all` enumerates them), cycled. The batch compiles each distinct stage
// text once, so this now measures the 11 variants plus 189 reuses; BM_DistinctBatch is
// the per-variant figure.
//
// BM_VariantsAll/<shared>: the bundled graphs' `--variants all`, once, at 1 job: each
// variant compiled alone (0) or as one batch that compiles a stage text the variants
// share once (1). The counters give the share of shared stages.
#include <benchmark/benchmark.h>

#include "bench/bundled_variants.hpp"

namespace {

constexpr std::size_t kCompiles = 200;

void batch(benchmark::State& state) {
  const std::vector<wg::CompileJob> variants = wg::bench::bundledVariants();
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

void variantsAll(benchmark::State& state) {
  const std::vector<wg::CompileJob> variants = wg::bench::bundledVariants();
  const bool shared = state.range(0) != 0;
  wg::SpirvModuleCache::Counts counts;
  for (auto _ : state) {
    wg::SpirvModuleCache modules;
    wg::CompileOptions options;
    if (shared) options.modules = &modules;
    for (const auto& job : variants) {
      options.switches = job.switches;
      auto result = wg::compileMaterialFile(job.graph, options);
      benchmark::DoNotOptimize(result);
    }
    counts = modules.counts();
  }
  state.counters["variants"] = static_cast<double>(variants.size());
  state.counters["stages"] = static_cast<double>(variants.size() * 4);
  if (shared) state.counters["distinct_stages"] = static_cast<double>(counts.compiled);
}

BENCHMARK(variantsAll)->Name("BM_VariantsAll")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
