// weathergen_gpu_shader_stats: what a GPU's own shader compiler makes of a material's
// lit pipeline (host/gpu_shader_statistics.hpp): registers, instructions, code size and
// waves per SIMD of its vertex and fragment stages, for the graph's weather and for
// preset none at each quality tier, as a markdown table. scripts/gpu-shader-stats.sh
// runs it for an AMD GPU family on RADV's null device; `weathergen stats --gpu` shows
// the main figures beside the SPIR-V ones.
//
//   weathergen_gpu_shader_stats [--device NAME] [--quality TIER] [--effects NAME=on|off,...] GRAPH...
//   --fragment-spirv FILE.spv  the weathered fragment stage read from FILE (a hand edit of
//                              the emitted GLSL through glslangValidator -V), to try a change
//                              of the shader library before making it
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>
#include <vector>

#include "compiler/diagnostic.hpp"
#include "compiler/quality_tiers.hpp"
#include "driver/material_compiler.hpp"
#include "host/gpu_shader_statistics.hpp"

namespace {

struct Options {
  std::string device;
  std::vector<std::string> tiers;
  wg::WeatherEffectOverrides effects;
  std::vector<std::string> graphs;
  std::string fragmentSpirv;
};

wg::SpirvWords readSpirv(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  wg::SpirvWords words(bytes.size() / 4, 0);
  std::memcpy(words.data(), bytes.data(), words.size() * 4);
  return words;
}

std::optional<wg::StageGpuStatistics> materialStatistics(wg::GpuShaderCompiler& gpu, const std::string& graph,
                                                         const std::string& tier,
                                                         const std::optional<std::string>& preset, const Options& o) {
  wg::CompileOptions options;
  options.emitHlsl = false;
  options.weatherPreset = preset;
  options.quality.requested = tier;
  options.weatherEffects = o.effects;
  wg::CompileResult result = wg::compileMaterialFile(graph, options);
  for (const auto& d : result.diagnostics.items()) std::fputs(wg::formatDiagnosticText(d).c_str(), stderr);
  if (!result.material) return std::nullopt;
  const wg::CompiledMaterial& m = *result.material;
  const bool replaced = !o.fragmentSpirv.empty() && !preset;
  return gpu.litPipeline(m.reflectionJson, m.stage(wg::ShaderLanguage::Glsl, wg::ShaderStage::Vertex).spirv,
                         replaced ? readSpirv(o.fragmentSpirv)
                                  : m.stage(wg::ShaderLanguage::Glsl, wg::ShaderStage::Fragment).spirv);
}

const char* const kColumns[] = {"VGPRs", "SGPRs", "Instructions", "Code size", "Subgroups per SIMD", "Latency",
                                "Inverse Throughput", "Branches", "Spilled VGPRs", "Pre-Sched VGPRs"};

void printRow(const std::string& material, const std::string& tier, const char* stage, const char* weather,
              const wg::ExecutableStatistics& stats) {
  std::printf("| %s | %s | %s | %s |", material.c_str(), tier.c_str(), stage, weather);
  for (const char* column : kColumns) {
    auto it = stats.find(column);
    if (it == stats.end()) std::printf(" - |");
    else std::printf(" %.0f |", it->second);
  }
  std::printf("\n");
}

bool parseArguments(int argc, char** argv, Options& o) {
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if ((a == "--device" || a == "--quality" || a == "--effects" || a == "--fragment-spirv") && i + 1 < argc) {
      const std::string v = argv[++i];
      if (a == "--device") o.device = v;
      if (a == "--fragment-spirv") o.fragmentSpirv = v;
      if (a == "--quality") o.tiers = {v};
      for (std::size_t at = 0; a == "--effects" && at < v.size();) {
        const std::size_t end = std::min(v.find(',', at), v.size());
        const std::string item = v.substr(at, end - at);
        const std::size_t eq = item.find('=');
        if (eq == std::string::npos) return false;
        o.effects.emplace_back(item.substr(0, eq), item.substr(eq + 1) == "on");
        at = end + 1;
      }
    } else if (a.starts_with("-")) {
      return false;
    } else {
      o.graphs.push_back(a);
    }
  }
  if (o.tiers.empty())
    for (const auto& t : wg::qualityTiers()) o.tiers.emplace_back(t.name);
  return !o.graphs.empty();
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  if (!parseArguments(argc, argv, o)) {
    std::fprintf(stderr,
                 "usage: %s [--device NAME] [--quality TIER] [--effects NAME=on|off,...] [--fragment-spirv FILE] "
                 "GRAPH...\n",
                 argv[0]);
    return 2;
  }
  std::string error;
  auto gpu = wg::GpuShaderCompiler::forDevice(o.device, error);
  if (!gpu) {
    std::fprintf(stderr, "%s\n", error.c_str());
    return 1;
  }
  std::printf("Device: %s. Lit colour pipeline, single-sampled, GLSL.\n\n| material | tier | stage | weather |",
              gpu->deviceName().c_str());
  for (const char* column : kColumns) std::printf(" %s |", column);
  std::printf("\n|---|---|---|---|");
  for (std::size_t i = 0; i < std::size(kColumns); ++i) std::printf("---:|");
  std::printf("\n");
  int failures = 0;
  for (const std::string& graph : o.graphs)
    for (const std::string& tier : o.tiers) {
      auto weathered = materialStatistics(*gpu, graph, tier, std::nullopt, o);
      auto none = materialStatistics(*gpu, graph, tier, "none", o);
      if (!weathered || !none) {
        ++failures;
        continue;
      }
      const std::string material = std::filesystem::path(graph).stem().string();
      printRow(material, tier, "vert", "none", none->vertex);
      printRow(material, tier, "vert", "graph's", weathered->vertex);
      printRow(material, tier, "frag", "none", none->fragment);
      printRow(material, tier, "frag", "graph's", weathered->fragment);
    }
  return failures ? 1 : 0;
}
