// weathergen_spirv_stats: for each graph and each stage/language, the emitted source
// size and the SPIR-V instruction count straight from glslang (-O0) and after spirv-opt's
// performance recipe (optimizeSpirv), as a markdown table. Used to report weather cost.
//
//   weathergen_spirv_stats            every bundled graphs/*.json
//   weathergen_spirv_stats a.json...  the given graph files
#include <cstdio>
#include <string>
#include <vector>

#include "bench/bench_common.hpp"
#include "compiler/material_compiler.hpp"

int main(int argc, char** argv) {
  std::vector<wg::bench::BundledGraph> graphs;
  for (int i = 1; i < argc; ++i)
    graphs.push_back({std::filesystem::path(argv[i]).stem().string(), argv[i]});
  if (argc == 1) graphs = wg::bench::bundledGraphs();
  if (graphs.empty()) {
    std::fprintf(stderr, "no graphs found under %s\n", wg::bench::graphsDirectory().string().c_str());
    return 1;
  }
  int failures = 0;
  std::printf("| graph | stage | language | source bytes | SPIR-V instructions -O0 | after spirv-opt |\n");
  std::printf("|---|---|---|---:|---:|---:|\n");
  for (const auto& graph : graphs) {
    auto result = wg::compileMaterialText(graph.path, wg::bench::readText(graph.path), {.emitSpirv = true});
    if (!result.material) {
      for (const auto& d : result.diagnostics.items()) std::fputs(wg::formatDiagnosticText(d).c_str(), stderr);
      std::printf("| %s | - | - | - | does not compile | - |\n", graph.stem.c_str());
      ++failures;
      continue;
    }
    for (wg::ShaderStage stage : {wg::ShaderStage::Vertex, wg::ShaderStage::Fragment})
      for (wg::ShaderLanguage language : {wg::ShaderLanguage::Glsl, wg::ShaderLanguage::Hlsl}) {
        const auto& s = result.material->stage(language, stage);
        std::size_t o0 = wg::countInstructions(s.spirv);
        std::size_t opt = wg::countInstructions(wg::optimizeSpirv(s.spirv));
        std::printf("| %s | %s | %s | %zu | %zu | %zu |\n", graph.stem.c_str(),
                    stage == wg::ShaderStage::Vertex ? "vert" : "frag", std::string(wg::languageName(language)).c_str(),
                    s.source.size(), o0, opt);
      }
  }
  return failures == 0 ? 0 : 1;
}
