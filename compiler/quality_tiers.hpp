// Quality tiers: which of the weather's costs beyond seed 000's own terms a material
// pays, as engines' material quality levels do (docs/weather-model.md, "Quality
// tiers"). A tier switches the effects it names over the preset's; the graph's own
// "effects" and the caller's --effects still switch them after it.
#pragma once
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "compiler/weather_config.hpp"

namespace wg {

struct QualityTier {
  std::string_view name;
  std::string_view summary;  // for --help and the docs
  bool skyExposure;          // sheltered points get no snow, rain or puddles
  bool looks;                // relief, ripple and specular anti-aliasing
};

// low, medium, high: each adds to the one before.
std::span<const QualityTier> qualityTiers();
const QualityTier* findQualityTier(std::string_view name);  // nullptr: no such tier
std::string qualityTierList();                              // "low, medium, high"

// Which tier a compile asks for: the caller's (--quality, Options::quality), else the
// graph's "weather": {"quality": ...}, else the targets' default (GLSL ES and MSL, for
// mobile GPUs: low; the rest: high).
struct QualityChoice {
  std::optional<std::string> requested;
  std::string fallback = "high";
};

// Sets the effects the tier governs; the preset's other effects stay as they are.
void applyQualityTier(const QualityTier& tier, WeatherEffects& effects);

}  // namespace wg
