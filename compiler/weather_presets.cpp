// Weather presets reproduce seed 000, chapter 5, and the graph's "weather" block
// overrides them.
#include <algorithm>
#include <cmath>

#include "compiler/literal.hpp"
#include "compiler/weather_config.hpp"

namespace wg {

namespace {

WeatherConfig makePreset(std::string name) {
  WeatherConfig c;
  c.preset = std::move(name);
  auto& e = c.effects;
  if (c.preset == "rock") {
    // Section 5.1.1: the complete prediction function suits complex meshes such as rocks.
    e.snow = e.displacement = e.terrainOrientation = e.moss = e.wetness = true;
  } else if (c.preset == "terrain") {
    // "For grassy parts, it uses only detail, height and wind functions."
    e.snow = e.displacement = e.wetness = true;
    c.terms = {0.f, 0.f, 1.f, 1.f};
  } else if (c.preset == "foliage") {
    // Detail mask only; alpha cards are not displaced; density falls as snow rises.
    e.snow = e.foliageDensity = true;
    c.terms = {0.f, 0.f, 0.f, 0.f};
  } else if (c.preset == "river") {
    // Eq. 3.20: freezes from the banks, then ice.
    e.ice = true;
  } else if (c.preset == "road") {
    // Figures 5.7 and 5.12: wetness, puddles and frost, no displacement.
    e.wetness = e.puddles = e.hoarfrost = true;
  }
  return c;
}

constexpr std::array<std::string_view, 6> kPresets = {"foliage", "none", "river", "road", "rock", "terrain"};

struct EffectFlag {
  std::string_view name;
  bool WeatherEffects::*flag;
};
constexpr std::array<EffectFlag, 10> kEffectFlags = {{
    {"snow", &WeatherEffects::snow},
    {"displacement", &WeatherEffects::displacement},
    {"terrainOrientation", &WeatherEffects::terrainOrientation},
    {"moss", &WeatherEffects::moss},
    {"wetness", &WeatherEffects::wetness},
    {"puddles", &WeatherEffects::puddles},
    {"ice", &WeatherEffects::ice},
    {"hoarfrost", &WeatherEffects::hoarfrost},
    {"foliageDensity", &WeatherEffects::foliageDensity},
    {"skyExposure", &WeatherEffects::skyExposure},
}};

struct NumberSetting {
  std::string_view name;
  float WeatherConfig::*field;
  float min, max;
};
constexpr std::array<NumberSetting, 7> kNumberSettings = {{
    {"maxSnowHeight", &WeatherConfig::maxSnowHeight, 0.f, 10.f},
    {"minHeight", &WeatherConfig::minHeight, -1e5f, 1e5f},
    {"maxHeight", &WeatherConfig::maxHeight, -1e5f, 1e5f},
    {"inclinationIntensity", &WeatherConfig::inclinationIntensity, 0.f, 4.f},
    {"terrainSlopeIntensity", &WeatherConfig::terrainSlopeIntensity, -1000.f, 1000.f},
    {"terrainIntensity", &WeatherConfig::terrainIntensity, -16.f, 16.f},
    {"foliageThinning", &WeatherConfig::foliageThinning, 0.f, 1.f},
}};

std::string presetList() {
  std::string out;
  for (auto p : kPresets) out += (out.empty() ? "" : ", ") + std::string(p);
  return out;
}

}  // namespace

std::vector<std::string_view> weatherPresetNames() { return {kPresets.begin(), kPresets.end()}; }

std::optional<WeatherConfig> weatherPreset(std::string_view name) {
  if (std::find(kPresets.begin(), kPresets.end(), name) == kPresets.end()) return std::nullopt;
  return makePreset(std::string(name));
}

std::optional<WeatherConfig> resolveWeatherConfig(const std::optional<nlohmann::json>& block, const std::string& pointer,
                                                  const std::optional<std::string>& presetOverride,
                                                  const JsonDocument& doc, DiagnosticList& diags) {
  bool ok = true;
  auto unknownPreset = [&](const std::string& name, SourceLocation where) {
    diags.report(DiagCode::UnknownWeatherPreset, std::move(where),
                 {quoteUserText(name), unknownNameHint(name, weatherPresetNames(), "presets")});
    ok = false;
  };
  auto invalid = [&](const std::string& at, const std::string& what, const std::string& fix) {
    diags.report(DiagCode::InvalidWeatherSetting, doc.locate(at), {what, fix});
    ok = false;
  };

  std::string presetName = "none";
  std::string presetPointer = pointer;
  const nlohmann::json* overrides = nullptr;
  if (block) {
    if (block->is_string()) {
      presetName = block->get<std::string>();
    } else if (block->is_object()) {
      overrides = &*block;
      if (auto it = block->find("preset"); it != block->end()) {
        presetPointer = appendPointer(pointer, "preset");
        if (!it->is_string()) invalid(presetPointer, "'preset' must be a string", "name a preset: " + presetList());
        else presetName = it->get<std::string>();
      } else {
        invalid(pointer, "the weather block has no 'preset'", "add \"preset\": one of " + presetList());
      }
    }
  }
  if (presetOverride) presetName = *presetOverride;
  auto config = weatherPreset(presetName);
  if (!config) {
    unknownPreset(presetName, presetOverride ? SourceLocation{} : doc.locate(presetPointer));
    return std::nullopt;
  }
  if (!overrides) return ok ? config : std::nullopt;

  for (const auto& [key, value] : overrides->items()) {
    std::string at = appendPointer(pointer, key);
    if (key == "preset" || key == "description") continue;
    if (key == "effects") {
      if (!value.is_object()) {
        invalid(at, "'effects' must be an object of booleans", "write e.g. {\"moss\": false}");
        continue;
      }
      for (const auto& [effect, on] : value.items()) {
        const std::string& effectName = effect;  // clang 14 cannot capture structured bindings
        auto flag = std::find_if(kEffectFlags.begin(), kEffectFlags.end(), [&](const EffectFlag& f) { return f.name == effectName; });
        std::string effectAt = appendPointer(at, effect);
        if (flag == kEffectFlags.end()) {
          std::vector<std::string_view> names;
          for (const auto& f : kEffectFlags) names.push_back(f.name);
          invalid(effectAt, "unknown weather effect '" + quoteUserText(effect) + "'", unknownNameHint(effect, names, "effects"));
        } else if (!on.is_boolean()) {
          invalid(effectAt, "effect '" + std::string(flag->name) + "' must be true or false", "write true or false");
        } else {
          config->effects.*(flag->flag) = on.get<bool>();
        }
      }
      continue;
    }
    if (key == "weights" || key == "terms") {
      auto& target = key == "weights" ? config->weights : config->terms;
      bool shaped = value.is_array() && value.size() == 4 &&
                    std::all_of(value.begin(), value.end(), [](const auto& x) { return x.is_number(); });
      if (!shaped) {
        invalid(at, "'" + key + "' must be an array of 4 numbers", key == "weights" ? "write [w1, w2, w3, w4]" : "write [inclination, sun, height, wind] as 0 or 1");
        continue;
      }
      for (std::size_t i = 0; i < 4; ++i) {
        float v = value[i].get<float>();
        bool inRange = key == "weights" ? (v >= 0.f && v <= 16.f) : (v == 0.f || v == 1.f);
        if (!inRange) {
          invalid(appendPointer(at, i), key + "[" + std::to_string(i) + "] is " + formatFloat(v),
                  key == "weights" ? "weights lie in [0, 16]" : "terms are 0 (off) or 1 (on)");
          break;
        }
        target[i] = v;
      }
      continue;
    }
    auto setting = std::find_if(kNumberSettings.begin(), kNumberSettings.end(),
                                [&keyName = key](const NumberSetting& s) { return s.name == keyName; });
    if (setting == kNumberSettings.end()) {
      std::vector<std::string_view> names = {"preset", "effects", "weights", "terms"};
      for (const auto& s : kNumberSettings) names.push_back(s.name);
      invalid(at, "unknown weather setting '" + quoteUserText(key) + "'", unknownNameHint(key, names, "settings"));
      continue;
    }
    if (!value.is_number() || !std::isfinite(value.get<double>())) {
      invalid(at, "'" + key + "' must be a finite number", "write a number");
      continue;
    }
    float v = value.get<float>();
    if (v < setting->min || v > setting->max) {
      invalid(at, "'" + key + "' is " + formatFloat(v) + ", outside [" + formatFloat(setting->min) + ", " +
                      formatFloat(setting->max) + "]",
              "use a value in that range");
      continue;
    }
    (*config).*(setting->field) = v;
  }
  if (config->minHeight >= config->maxHeight)
    invalid(pointer, "minHeight " + formatFloat(config->minHeight) + " is not below maxHeight " + formatFloat(config->maxHeight),
            "make minHeight smaller than maxHeight");
  return ok ? config : std::nullopt;
}

}  // namespace wg
