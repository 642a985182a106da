// BM_DistinctBatch/<jobs>: 200 compiles with SPIR-V, no two alike (distinct content
// hashes): every bundled graph under every weather preset and every static-switch
// variant, topped up with synthetic graphs. Unlike BM_Batch, which cycles 11 variants,
// no compile can reuse another's work except for stage texts variants truly share.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <fstream>
#include <set>

#include "bench/bundled_variants.hpp"
#include "bench/synthetic_graph.hpp"
#include "driver/batch_compile.hpp"

namespace {

constexpr std::size_t kCompiles = 200;
constexpr const char* kPresets[] = {"none", "foliage", "river", "road", "rock", "terrain"};

std::vector<wg::CompileJob> candidateJobs() {
  std::vector<wg::CompileJob> jobs;
  for (const auto& variant : wg::bench::bundledVariants())
    for (const char* preset : kPresets) {
      jobs.push_back(variant);
      jobs.back().weatherPreset = preset;
    }
  return jobs;
}

// Synthetic graphs of 40-240 nodes, written once where the benchmark can read them.
std::vector<wg::CompileJob> syntheticJobs(std::size_t count) {
  auto dir = std::filesystem::temp_directory_path() / "weathergen-distinct-batch";
  std::filesystem::create_directories(dir);
  std::vector<wg::CompileJob> jobs;
  for (std::size_t i = 0; i < count; ++i) {
    auto path = dir / ("synthetic" + std::to_string(i) + ".json");
    std::ofstream(path, std::ios::binary) << wg::makeSyntheticGraph(40 + static_cast<int>(i % 6) * 40, 7000u + i);
    jobs.push_back({path.string(), {}, std::string(kPresets[i % std::size(kPresets)])});
  }
  return jobs;
}

// The first kCompiles jobs whose materials differ (by content hash).
std::vector<wg::CompileJob> distinctJobs() {
  std::vector<wg::CompileJob> candidates = candidateJobs();
  auto synthetic = syntheticJobs(kCompiles);
  candidates.insert(candidates.end(), synthetic.begin(), synthetic.end());
  const wg::CompileOptions textOnly{.emitSpirv = false, .emitReflection = false};
  auto results = wg::compileBatch(candidates, textOnly, 1);
  std::set<std::string> seen;
  std::vector<wg::CompileJob> jobs;
  for (std::size_t i = 0; i < candidates.size() && jobs.size() < kCompiles; ++i)
    if (results[i].material && seen.insert(results[i].material->contentHash).second) jobs.push_back(candidates[i]);
  return jobs;
}

void distinctBatch(benchmark::State& state) {
  static const std::vector<wg::CompileJob> jobs = distinctJobs();
  if (jobs.size() < kCompiles) {
    state.SkipWithError("fewer than 200 distinct variants");
    return;
  }
  wg::SpirvModuleCache::Counts counts;
  for (auto _ : state) {
    wg::SpirvModuleCache modules;  // one per batch, as compileBatch makes it
    wg::CompileOptions options;    // SPIR-V included, as a build step runs it
    options.modules = &modules;
    auto results = wg::compileBatch(jobs, options, static_cast<int>(state.range(0)));
    benchmark::DoNotOptimize(results);
    counts = modules.counts();
  }
  state.counters["compiles"] = static_cast<double>(jobs.size());
  state.counters["stages"] = static_cast<double>(counts.lookups);
  state.counters["distinct_stages"] = static_cast<double>(counts.compiled);
  state.counters["ms_per_variant"] = benchmark::Counter(static_cast<double>(jobs.size()) / 1000.0,
                                                        benchmark::Counter::kIsIterationInvariantRate |
                                                            benchmark::Counter::kInvert);
}

BENCHMARK(distinctBatch)->Name("BM_DistinctBatch")->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime()
    ->Iterations(1)->Repetitions(3)->ReportAggregatesOnly(true);

}  // namespace
