// What the weather-inject pass adds to a material: a preset (seed 000, chapter 5) plus
// the graph's overrides. Settings here are compile-time constants, so a disabled
// effect folds away entirely; w1-w4, maxSnowHeight and the height range become
// material parameters that artists can tune at run time.
#pragma once
#include <array>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "compiler/diagnostic.hpp"
#include "compiler/json_document.hpp"

namespace wg {

struct WeatherEffects {
  bool snow = false;
  bool displacement = false;        // eq. 3.10, vertex stage
  bool terrainOrientation = false;  // eq. 3.11-3.13
  bool moss = false;
  bool wetness = false;  // eq. 3.15-3.18
  bool puddles = false;  // section 5.1.2
  bool ice = false;      // eq. 3.20 frost mask from the banks, then ice
  bool hoarfrost = false;  // frost crystals on exposed ground
  bool foliageDensity = false;  // foliage thins under snow
  bool skyExposure = true;      // sheltered points get no snow, rain or puddles
  // Per-pixel looks, on wherever their layer is; each costs texture lookups or
  // derivatives (docs/weather-model.md, "Looks beyond the seed").
  bool relief = true;                // snow's and ice's own lit micro-relief
  bool ripple = true;                // eq. 3.18's rain ripple on wet surfaces
  bool specularAntiAliasing = true;  // wet roughness widened by the normal's pixel variance
};

// Each effect's key in a graph's "effects" block and in the reflection.
struct WeatherEffectFlag {
  std::string_view name;
  bool WeatherEffects::*flag;
};
inline constexpr std::size_t kWeatherEffectCount = 13;
const std::array<WeatherEffectFlag, kWeatherEffectCount>& weatherEffectFlags();
const WeatherEffectFlag* findWeatherEffectFlag(std::string_view name);  // nullptr: no such effect

// A second preset for the steep parts (section 5.1.1: a terrain's "cliff and rocky parts"
// take the complete prediction, its grassy parts only height and wind), blended in by
// the geometric normal's slope.
struct SteepBlend {
  std::string preset;
  std::array<float, 4> terms{1.f, 1.f, 1.f, 1.f};  // the steep preset's eq. 3.1 switches
  float fromDegrees = 30.f, toDegrees = 45.f;        // all flat below, all steep above
};

struct WeatherConfig {
  std::string preset = "none";
  std::optional<SteepBlend> steep;
  std::string quality = "high";  // the tier applied (compiler/quality_tiers.hpp)
  WeatherEffects effects;
  // Eq. 3.1 switches: inclination, sun, height, wind (a factor switched off counts as 1).
  std::array<float, 4> terms{1.f, 1.f, 1.f, 1.f};
  std::array<float, 4> weights{2.f, 0.5f, 2.f, 0.5f};  // w1 sun, w2 wind, w3 height, w4 terrain
  float maxSnowHeight = 0.25f;  // metres: the seed's test scene uses 25 cm
  float minHeight = -50.f, maxHeight = 50.f;  // metres, eq. 3.8
  float inclinationIntensity = 0.5f;  // eq. 3.4's normal-map term
  float terrainSlopeIntensity = 10.f;  // eq. 3.12: height-map differences are small over 0.05 uv
  float terrainIntensity = 1.f;        // eq. 3.13
  float foliageThinning = 0.8f;        // share of foliage cards removed under full snow

  bool active() const { return preset != "none"; }
};

// Effects a caller switches on or off over every graph's own, after the graph's
// "effects" block: compile, render and bench-render's --effects, Options::effects.
using WeatherEffectOverrides = std::vector<std::pair<std::string, bool>>;

std::vector<std::string_view> weatherPresetNames();
std::optional<WeatherConfig> weatherPreset(std::string_view name);

struct QualityChoice;

// Resolves the graph's "weather" value (a preset name or an object with "preset" and
// overrides), with presetOverride (the CLI's --weather-preset) replacing the preset,
// then the quality tier (the caller's, the block's "quality" or the fallback), then
// the block's own overrides, and effectOverrides last while the weather is active.
// Reports WG4001-WG4009 (an unknown overridden effect or tier as WG4006, without a
// location, whether or not the weather is active) and returns nullopt on errors.
std::optional<WeatherConfig> resolveWeatherConfig(const std::optional<nlohmann::json>& block,
                                                  const std::string& pointer,
                                                  const std::optional<std::string>& presetOverride,
                                                  const QualityChoice& quality,
                                                  const WeatherEffectOverrides& effectOverrides,
                                                  const JsonDocument& document, DiagnosticList& diagnostics);

}  // namespace wg
