// Quality tiers: which of the weather's costs beyond seed 000's own terms a material
// pays, as engines' material quality levels do (docs/weather-model.md, "Quality
// tiers"). A tier switches the effects it names over the preset's; the graph's own
// "effects" and the caller's --effects still switch them after it.
#pragma once
#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "compiler/material_graph.hpp"
#include "compiler/static_switches.hpp"
#include "compiler/weather_config.hpp"
#include "nodes/shader_stage.hpp"

namespace wg {

struct QualityTier {
  std::string_view name;
  std::string_view summary;  // for --help and the docs
  bool skyExposure;          // sheltered points get no snow, rain or puddles
  bool looks;                // relief, ripple and specular anti-aliasing
  // Static budgets: SPIR-V instructions the weather may add after spirv-opt, GLSL
  // (weathergen stats; docs/BENCHMARKS.md, "Quality tiers").
  int fragmentBudget;
  int vertexBudget;
};

// low, medium, high: each adds to the one before.
std::span<const QualityTier> qualityTiers();
const QualityTier* findQualityTier(std::string_view name);  // nullptr: no such tier
std::string qualityTierList();                              // "low, medium, high"
int weatherBudget(const QualityTier& tier, ShaderStage stage);

// Which tier a compile asks for: the caller's (--quality, Options::quality), else the
// graph's "weather": {"quality": ...}, else the targets' default (GLSL ES and MSL, for
// mobile GPUs: low; the rest: high).
struct QualityChoice {
  std::optional<std::string> requested;
  std::string fallback = "high";
};

// Sets the effects the tier governs; the preset's other effects stay as they are.
void applyQualityTier(const QualityTier& tier, WeatherEffects& effects);

// The tier is the static switch "quality" (docs/graph-format.md, "Static switches"):
// --variants enumerates it for every graph, and a graph's own switch of that name
// follows the tier.
inline constexpr std::string_view kQualitySwitch = "quality";

// The tier's name before the graph is built, in QualityChoice's order; a graph's
// "quality" that names no tier is skipped here (resolveWeatherConfig reports it).
std::string chosenTierName(const QualityChoice& quality, const std::optional<nlohmann::json>& weatherBlock);

// The axes --variants enumerates: the declared switches (sorted by name) and the tiers
// as "quality", defaulting to `defaultTier`; a graph's own "quality" stays, defaulting
// to `defaultTier` where it has that value.
std::vector<SwitchDecl> withQualityAxis(std::vector<SwitchDecl> declared, const std::string& defaultTier);

// A graph's own switch "quality": a variant that names a tier with it picks that tier;
// left unnamed, it takes the compile's tier where it has that value.
void bindQualitySwitch(const MaterialGraph& graph, SwitchValues& switches, QualityChoice& quality);

}  // namespace wg
