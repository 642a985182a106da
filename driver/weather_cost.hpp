// What the weather adds to a material's shaders at one quality tier, as a material
// stats panel shows it (weathergen stats, weathergen_spirv_stats --tiers): per stage
// and language, the SPIR-V after spirv-opt and the instructions it has beyond the same
// graph with preset none at the same tier (a graph's own "quality" switch follows the
// tier, and what it drops from the material is not the weather's).
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "backends/spirv/spirv_toolchain.hpp"
#include "driver/material_compiler.hpp"

namespace wg {

struct StageCost {
  ShaderStage stage;
  ShaderLanguage language;
  SpirvStatistics spirv;  // after spirv-opt
  long weather = 0;       // instructions the weather adds
};

struct WeatherCost {
  CompiledMaterial material;      // weathered, at the tier
  CompiledMaterial none;          // the same graph with preset none, at the tier
  std::vector<StageCost> stages;  // vertex then fragment; GLSL then HLSL
};

// `preset` replaces the graph's own (nullopt: its own). Nullopt when a compile fails;
// its diagnostics are added to `diagnostics`.
std::optional<WeatherCost> weatherCostAtTier(const std::string& graph, const std::string& tier,
                                             const std::optional<std::string>& preset, DiagnosticList& diagnostics);

}  // namespace wg
