// BM_Synthetic/<n>: the codegen path (emitSpirv = false) on generated graphs of n
// nodes (bench/synthetic_graph.hpp), for the scaling targets t(10k) and t(10k)/t(1k).
#include <benchmark/benchmark.h>

#include "bench/synthetic_graph.hpp"
#include "driver/material_compiler.hpp"

namespace {

constexpr std::uint32_t kSeed = 20240601;

void synthetic(benchmark::State& state) {
  const int nodeCount = static_cast<int>(state.range(0));
  const std::string text = wg::makeSyntheticGraph(nodeCount, kSeed);
  const wg::CompileOptions options{.emitSpirv = false};
  auto first = wg::compileMaterialText("synthetic.json", text, options);
  if (!first.material) {
    std::string message = "synthetic graph does not compile";
    for (const auto& d : first.diagnostics.items()) {
      message += ": " + wg::formatDiagnosticText(d);
      break;
    }
    state.SkipWithError(message.c_str());
    return;
  }
  for (auto _ : state) {
    auto result = wg::compileMaterialText("synthetic.json", text, options);
    benchmark::DoNotOptimize(result);
  }
  const auto& m = *first.material;
  state.counters["nodes"] = nodeCount;
  state.counters["surviving_nodes"] = static_cast<double>(m.ir.nodes.size());
  state.counters["json_bytes"] = static_cast<double>(text.size());
  state.counters["glsl_frag_bytes"] =
      static_cast<double>(m.stage(wg::ShaderLanguage::Glsl, wg::ShaderStage::Fragment).source.size());
  state.SetComplexityN(nodeCount);
}

BENCHMARK(synthetic)->Name("BM_Synthetic")->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);

}  // namespace
