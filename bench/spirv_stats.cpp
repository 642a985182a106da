// weathergen_spirv_stats: for each graph and each stage/language, the emitted source
// size and the SPIR-V instruction count straight from glslang (-O0) and after spirv-opt's
// performance recipe (optimizeSpirv), as a markdown table. Used to report weather cost.
//
//   weathergen_spirv_stats                     every bundled graphs/*.json
//   weathergen_spirv_stats a.json...           the given graph files
//   weathergen_spirv_stats --weather-cost      per bundled graph, stage and language: the
//                                              instruction count after spirv-opt with the
//                                              graph's own preset and with preset "none",
//                                              and the difference; then what each effect
//                                              adds to rock (the preset minus that effect)
//   weathergen_spirv_stats --tiers             per bundled weathered graph and stage: what
//                                              the weather adds at each quality tier
//                                              (GLSL), against the tiers' budgets, as
//                                              docs/BENCHMARKS.md quotes it
//   weathergen_spirv_stats --weather-functions one probe graph per weather op: what the
//                                              op (its library function, inlined) adds
//                                              to a minimal material after spirv-opt
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <cstring>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "bench/bench_common.hpp"
#include "compiler/quality_tiers.hpp"
#include "driver/material_compiler.hpp"
#include "driver/weather_cost.hpp"
#include "nodes/op_registry.hpp"

namespace {

using wg::ShaderLanguage;
using wg::ShaderStage;

constexpr ShaderLanguage kLanguages[] = {ShaderLanguage::Glsl, ShaderLanguage::Hlsl};
constexpr ShaderStage kStages[] = {ShaderStage::Fragment, ShaderStage::Vertex};

const char* stageName(ShaderStage s) { return s == ShaderStage::Vertex ? "vert" : "frag"; }

void printDiagnostics(const wg::CompileResult& r) {
  for (const auto& d : r.diagnostics.items()) std::fputs(wg::formatDiagnosticText(d).c_str(), stderr);
}

std::size_t optimizedCount(const wg::CompiledMaterial& m, ShaderLanguage language, ShaderStage stage) {
  return wg::countInstructions(wg::optimizeSpirv(m.stage(language, stage).spirv));
}

long delta(std::size_t with, std::size_t without) { return static_cast<long>(with) - static_cast<long>(without); }

int sourceStats(const std::vector<wg::bench::BundledGraph>& graphs) {
  int failures = 0;
  std::printf("| graph | stage | language | source bytes | SPIR-V instructions -O0 | after spirv-opt |\n");
  std::printf("|---|---|---|---:|---:|---:|\n");
  for (const auto& graph : graphs) {
    auto result = wg::compileMaterialText(graph.path, wg::bench::readText(graph.path), {.emitSpirv = true});
    if (!result.material) {
      printDiagnostics(result);
      std::printf("| %s | - | - | - | does not compile | - |\n", graph.stem.c_str());
      ++failures;
      continue;
    }
    for (ShaderStage stage : {ShaderStage::Vertex, ShaderStage::Fragment})
      for (ShaderLanguage language : kLanguages) {
        const auto& s = result.material->stage(language, stage);
        std::size_t o0 = wg::countInstructions(s.spirv);
        std::size_t opt = wg::countInstructions(wg::optimizeSpirv(s.spirv));
        std::printf("| %s | %s | %s | %zu | %zu | %zu |\n", graph.stem.c_str(), stageName(stage),
                    std::string(wg::languageName(language)).c_str(), s.source.size(), o0, opt);
      }
  }
  return failures;
}

// The graph's own preset against "none", per stage and language; then rock's effects.
int weatherCost(const std::vector<wg::bench::BundledGraph>& graphs) {
  int failures = 0;
  std::printf("| graph | preset | stage | language | none | with preset | difference |\n");
  std::printf("|---|---|---|---|---:|---:|---:|\n");
  for (const auto& graph : graphs) {
    const std::string text = wg::bench::readText(graph.path);
    auto with = wg::compileMaterialText(graph.path, text, {.emitSpirv = true});
    auto without = wg::compileMaterialText(graph.path, text, {.emitSpirv = true, .weatherPreset = "none"});
    if (!with.material || !without.material) {
      printDiagnostics(with.material ? without : with);
      std::printf("| %s | - | - | - | does not compile | - | - |\n", graph.stem.c_str());
      ++failures;
      continue;
    }
    for (ShaderStage stage : kStages)
      for (ShaderLanguage language : kLanguages) {
        std::size_t a = optimizedCount(*without.material, language, stage);
        std::size_t b = optimizedCount(*with.material, language, stage);
        std::printf("| %s | %s | %s | %s | %zu | %zu | %+ld |\n", graph.stem.c_str(), with.material->ir.weather.preset.c_str(),
                    stageName(stage), std::string(wg::languageName(language)).c_str(), a, b, delta(b, a));
      }
  }

  // What each of rock's effects adds: the full preset minus the preset without it.
  const std::string rockPath = (wg::bench::graphsDirectory() / "rock.json").string();
  auto rock = nlohmann::json::parse(wg::bench::readText(rockPath), nullptr, false);
  if (rock.is_discarded()) return failures + 1;
  auto compileRock = [&](const nlohmann::json& weather) {
    auto graph = rock;
    graph["weather"] = weather;
    return wg::compileMaterialText(rockPath, graph.dump(), {.emitSpirv = true});
  };
  auto full = compileRock("rock");
  if (!full.material) {
    printDiagnostics(full);
    return failures + 1;
  }
  std::printf("\n| rock effect switched off | frag glsl | frag hlsl | vert glsl | vert hlsl |\n");
  std::printf("|---|---:|---:|---:|---:|\n");
  for (const char* effect : {"snow", "displacement", "terrainOrientation", "moss", "wetness", "skyExposure"}) {
    auto reduced = compileRock({{"preset", "rock"}, {"effects", {{effect, false}}}});
    if (!reduced.material) {
      printDiagnostics(reduced);
      ++failures;
      continue;
    }
    std::printf("| %s |", effect);
    for (ShaderStage stage : kStages)
      for (ShaderLanguage language : kLanguages)
        std::printf(" %+ld |", delta(optimizedCount(*reduced.material, language, stage),
                                     optimizedCount(*full.material, language, stage)));
    std::printf("\n");
  }
  return failures;
}

// A minimal material whose baseColor, roughness and position offset read varying inputs;
// `probe` (a node id) is added onto the output matching its type.
std::string probeGraph(const wg::OpDef* op) {
  nlohmann::ordered_json g;
  g["name"] = "probe";
  g["parameters"] = {
      {"weights", {{"type", "vec4"}, {"default", {2, 0.5, 2, 0.5}}}},
      {"shape", {{"type", "vec4"}, {"default", {-50, 50, 0.5, 0}}}},
      {"terms", {{"type", "vec4"}, {"default", {1, 1, 1, 1}}}},
      {"scalar", {{"type", "float"}, {"default", 0.25}}},
  };
  nlohmann::ordered_json nodes = nlohmann::ordered_json::array();
  auto node = [&](const std::string& id, const std::string& opName, nlohmann::ordered_json inputs = nullptr,
                  const char* param = nullptr) {
    nlohmann::ordered_json n = {{"id", id}, {"op", opName}};
    if (!inputs.is_null()) n["inputs"] = std::move(inputs);
    if (param) n["param"] = param;
    nodes.push_back(std::move(n));
  };
  node("uv", "texcoord");
  node("uvParts", "split", {{"in", "uv.out"}});
  node("n", "world_normal");
  node("p", "world_position");
  node("vc", "vertex_color");
  node("c", "swizzle", {{"in", "vc.out"}, {"channels", "rgb"}});
  for (const char* param : {"weights", "shape", "terms", "scalar"}) node(std::string("param_") + param, "parameter", nullptr, param);
  nlohmann::ordered_json output = {{"baseColor", "c.out"}, {"roughness", "uvParts.x"}};
  if (op) {
    nlohmann::ordered_json inputs = nlohmann::ordered_json::object();
    for (const auto& port : op->inputs) {
      std::string name(port.name);
      switch (port.type) {
        case wg::PortType::Vec3:
          inputs[name] = name == "position" ? "p.out" : name == "diffuse" ? "c.out" : "n.out";
          break;
        case wg::PortType::Vec2:
          inputs[name] = "uv.out";
          break;
        case wg::PortType::Vec4:
          // The weather pass feeds weights and the height shape from material parameters.
          if (name == "weights" || name == "shape" || name == "terms") inputs[name] = "param_" + name + ".out";
          break;
        case wg::PortType::Float:
          if (name == "maxSnowHeight") inputs[name] = "param_scalar.out";
          else if (!port.defaultValue) inputs[name] = "uvParts.y";
          break;
        default:
          break;
      }
    }
    node("probe", std::string(op->name), inputs);
    std::string value = "probe." + std::string(op->outputs.empty() ? "out" : op->outputs.front().name);
    if (op->name == "weather_snow_offset") {
      output["worldPositionOffset"] = value;
    } else if (op->valueType == wg::ValueType::Vec3) {
      node("sum", "add", {{"a", "c.out"}, {"b", value}});
      output["baseColor"] = "sum.out";
    } else {
      // A whole vector (the first output reads no swizzle) is split to a float first.
      if (op->valueType != wg::ValueType::Float && (op->outputs.empty() || op->outputs.front().accessor.empty())) {
        node("probeParts", "split", {{"in", value}});
        value = "probeParts.x";
      }
      node("sum", "add", {{"a", "uvParts.x"}, {"b", value}});
      output["roughness"] = "sum.out";
    }
  }
  g["nodes"] = nodes;
  g["output"] = output;
  return g.dump(1);
}

int weatherFunctions() {
  const wg::CompileOptions options{.emitSpirv = true, .weatherPreset = "none"};
  auto base = wg::compileMaterialText("probe.json", probeGraph(nullptr), options);
  if (!base.material) {
    printDiagnostics(base);
    return 1;
  }
  int failures = 0;
  std::printf("| op (library function) | frag glsl | frag hlsl | vert glsl | vert hlsl |\n");
  std::printf("|---|---:|---:|---:|---:|\n");
  std::vector<const wg::OpDef*> ops;
  for (const wg::OpDef* op : wg::allOps())
    if (op->category == "weather") ops.push_back(op);
  // For reference: the value noise most coverage functions are built on.
  if (const wg::OpDef* noise = wg::findOp("value_noise")) ops.push_back(noise);
  for (const wg::OpDef* op : ops) {
    auto probe = wg::compileMaterialText("probe.json", probeGraph(op), options);
    if (!probe.material) {
      printDiagnostics(probe);
      std::printf("| %s | does not compile | | | |\n", std::string(op->name).c_str());
      ++failures;
      continue;
    }
    std::printf("| %s |", std::string(op->name).c_str());
    for (ShaderStage stage : kStages)
      for (ShaderLanguage language : kLanguages)
        std::printf(" %+ld |", delta(optimizedCount(*probe.material, language, stage),
                                     optimizedCount(*base.material, language, stage)));
    std::printf("\n");
  }
  return failures;
}

}  // namespace

// One row per graph and stage with the weather's instructions at each tier (GLSL), the
// budgets, and the largest HLSL - GLSL difference; graphs without weather are left out.
int tierCosts(const std::vector<wg::bench::BundledGraph>& graphs) {
  int failures = 0;
  std::printf("| material | stage | low | medium | high | budget low / medium / high | over | HLSL - GLSL |\n");
  std::printf("|---|---|---:|---:|---:|---|---|---:|\n");
  for (const auto& graph : graphs) {
    std::map<ShaderStage, std::string> costs, budgets, over;
    std::map<ShaderStage, long> hlslDrift, glsl;
    bool weathered = false;
    for (const wg::QualityTier& tier : wg::qualityTiers()) {
      wg::DiagnosticList diagnostics;
      auto cost = wg::weatherCostAtTier(graph.path, std::string(tier.name), std::nullopt, diagnostics);
      if (!cost) {
        for (const auto& d : diagnostics.items()) std::fputs(wg::formatDiagnosticText(d).c_str(), stderr);
        ++failures;
        break;
      }
      weathered = weathered || cost->material.ir.weather.active();
      for (const wg::StageCost& c : cost->stages) {
        if (c.language == ShaderLanguage::Glsl) {
          const int budget = wg::weatherBudget(tier, c.stage);
          glsl[c.stage] = c.weather;
          costs[c.stage] += (costs[c.stage].empty() ? "" : " | ") + std::string(c.weather >= 0 ? "+" : "") + std::to_string(c.weather);
          budgets[c.stage] += (budgets[c.stage].empty() ? "" : " / ") + std::to_string(budget);
          if (c.weather > budget) over[c.stage] += (over[c.stage].empty() ? "" : ", ") + std::string(tier.name);
        } else {
          hlslDrift[c.stage] = std::max(hlslDrift[c.stage], std::abs(c.weather - glsl[c.stage]));
        }
      }
    }
    if (!weathered) continue;
    for (ShaderStage stage : {ShaderStage::Vertex, ShaderStage::Fragment})
      std::printf("| %s | %s | %s | %s | %s | %ld |\n", graph.stem.c_str(), stageName(stage), costs[stage].c_str(),
                  budgets[stage].c_str(), over[stage].empty() ? "-" : over[stage].c_str(), hlslDrift[stage]);
  }
  return failures;
}

int main(int argc, char** argv) {
  if (argc == 2 && std::strcmp(argv[1], "--weather-cost") == 0) return weatherCost(wg::bench::bundledGraphs()) == 0 ? 0 : 1;
  if (argc == 2 && std::strcmp(argv[1], "--tiers") == 0) return tierCosts(wg::bench::bundledGraphs()) == 0 ? 0 : 1;
  if (argc == 2 && std::strcmp(argv[1], "--weather-functions") == 0) return weatherFunctions() == 0 ? 0 : 1;
  std::vector<wg::bench::BundledGraph> graphs;
  for (int i = 1; i < argc; ++i)
    graphs.push_back({std::filesystem::path(argv[i]).stem().string(), argv[i]});
  if (argc == 1) graphs = wg::bench::bundledGraphs();
  if (graphs.empty()) {
    std::fprintf(stderr, "no graphs found under %s\n", wg::bench::graphsDirectory().string().c_str());
    return 1;
  }
  return sourceStats(graphs) == 0 ? 0 : 1;
}
