// BM_Codegen/<graph>: the whole compiler short of glslang, for each bundled graph:
// parse + load + validate + IR + passes + GLSL and HLSL for both stages + reflection
// (compileMaterialText with emitSpirv = false). The JSON text is already in memory.
// Counters report each emitted shader's size in bytes.
#include <benchmark/benchmark.h>

#include <weathergen/weathergen.hpp>

#include "bench/bench_common.hpp"
#include "driver/material_compiler.hpp"

namespace {

// The codegen target: load + validate + passes + GLSL and HLSL for both
// stages; no glslang and no reflection JSON (BM_CompileNoSpirv adds that).
void codegen(benchmark::State& state, const wg::bench::BundledGraph& graph, bool reflection, bool weather) {
  const std::string text = wg::bench::readText(graph.path);
  wg::CompileOptions options{.emitSpirv = false, .emitReflection = reflection};
  if (!weather) options.weatherPreset = "none";
  auto first = wg::compileMaterialText(graph.path, text, options);
  if (!first.material) {
    state.SkipWithError(("does not compile: " + graph.path).c_str());
    return;
  }
  for (auto _ : state) {
    auto result = wg::compileMaterialText(graph.path, text, options);
    benchmark::DoNotOptimize(result);
  }
  const auto& m = *first.material;
  using L = wg::ShaderLanguage;
  using S = wg::ShaderStage;
  state.counters["glsl_vert_bytes"] = static_cast<double>(m.stage(L::Glsl, S::Vertex).source.size());
  state.counters["glsl_frag_bytes"] = static_cast<double>(m.stage(L::Glsl, S::Fragment).source.size());
  state.counters["hlsl_vert_bytes"] = static_cast<double>(m.stage(L::Hlsl, S::Vertex).source.size());
  state.counters["hlsl_frag_bytes"] = static_cast<double>(m.stage(L::Hlsl, S::Fragment).source.size());
  state.counters["ir_nodes"] = static_cast<double>(m.ir.nodes.size());
}

// The engine API asked for what BM_Codegen makes: shader text, no SPIR-V, no reflection.
void publicCodegen(benchmark::State& state, const wg::bench::BundledGraph& graph) {
  const std::string text = wg::bench::readText(graph.path);
  weathergen::Options options;
  options.spirv = false;
  options.reflection = false;
  for (auto _ : state) {
    auto result = weathergen::compile(graph.path, text, options);
    if (!result.ok) state.SkipWithError(("does not compile: " + graph.path).c_str());
    benchmark::DoNotOptimize(result);
  }
}

const bool registered = [] {
  for (const auto& graph : wg::bench::bundledGraphs())
  {
    benchmark::RegisterBenchmark(("BM_Codegen/" + graph.stem).c_str(), codegen, graph, false, true)->Unit(benchmark::kMicrosecond);
    // The material alone: its weather preset replaced by "none".
    benchmark::RegisterBenchmark(("BM_CodegenNoWeather/" + graph.stem).c_str(), codegen, graph, false, false)
        ->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark(("BM_CompileNoSpirv/" + graph.stem).c_str(), codegen, graph, true, true)
        ->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark(("BM_PublicCodegen/" + graph.stem).c_str(), publicCodegen, graph)
        ->Unit(benchmark::kMicrosecond);
  }
  return true;
}();

}  // namespace
