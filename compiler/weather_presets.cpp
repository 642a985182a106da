// Weather presets reproduce seed 000, chapter 5, and the graph's "weather" block
// overrides them.
#include <algorithm>
#include <cmath>

#include "compiler/literal.hpp"
#include "compiler/quality_tiers.hpp"
#include "compiler/weather_config.hpp"

namespace wg {

namespace {

// Effects that change nothing without the layers they act on are off, so a material's
// reflection and content hash say what its shaders do: two tiers that differ only in
// such effects give one shader set.
void clearDeadEffects(WeatherEffects& e) {
  const bool snowOrIce = e.snow || e.ice;
  e.skyExposure = e.skyExposure && (e.snow || e.wetness || e.puddles || e.hoarfrost || e.foliageDensity);
  e.displacement = e.displacement && e.snow;
  e.terrainOrientation = e.terrainOrientation && e.snow;
  e.relief = e.relief && snowOrIce;
  e.ripple = e.ripple && e.wetness;
  // Wet roughness, and the footprint-widened edges of melting snow's patches.
  e.specularAntiAliasing = e.specularAntiAliasing && (e.wetness || e.snow);
}

WeatherConfig makePreset(std::string name) {
  WeatherConfig c;
  c.preset = std::move(name);
  auto& e = c.effects;
  if (c.preset == "rock") {
    // Section 5.1.1: the complete prediction function suits complex meshes such as rocks.
    e.snow = e.displacement = e.terrainOrientation = e.moss = e.wetness = true;
    e.hoarfrost = true;  // exposed rock frosts over in a freeze, as roads do (figure 5.7)
  } else if (c.preset == "terrain") {
    // "For grassy parts, it uses only detail, height and wind functions."
    e.snow = e.displacement = e.wetness = true;
    e.hoarfrost = true;  // frosted ground reads as a freeze where little snow lies
    c.terms = {0.f, 0.f, 1.f, 1.f};
  } else if (c.preset == "foliage") {
    // Detail mask only; alpha cards are not displaced; density falls as snow rises.
    // Rain wets every object "regardless of their material" (5.1.2).
    e.snow = e.foliageDensity = e.wetness = true;
    c.terms = {0.f, 0.f, 0.f, 0.f};
  } else if (c.preset == "river") {
    // Eq. 3.20: freezes from the banks, then ice; rain wets the banks (5.1.2).
    e.ice = e.wetness = true;
  } else if (c.preset == "road") {
    // Figures 5.7 and 5.12: wetness, puddles and frost, no displacement.
    e.wetness = e.puddles = e.hoarfrost = true;
  }
  clearDeadEffects(c.effects);
  return c;
}

constexpr std::array<std::string_view, 6> kPresets = {"foliage", "none", "river", "road", "rock", "terrain"};

constexpr std::array<WeatherEffectFlag, kWeatherEffectCount> kEffectFlags = {{
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
    {"relief", &WeatherEffects::relief},
    {"ripple", &WeatherEffects::ripple},
    {"specularAntiAliasing", &WeatherEffects::specularAntiAliasing},
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

// Reports a bad weather setting at its JSON pointer; `ok` turns false with the first.
struct SettingErrors {
  const JsonDocument& doc;
  DiagnosticList& diags;
  bool ok = true;
  void report(DiagCode code, const std::string& at, std::initializer_list<std::string_view> args) {
    diags.report(code, doc.locate(at), args);
    ok = false;
  }
  // "weather {what} must be {expected}, not {actual}".
  void wrongKind(const std::string& at, const std::string& what, std::string_view expected, std::string_view actual) {
    report(DiagCode::WeatherSettingKind, at, {what, expected, actual});
  }
};

// The preset the block names: a string, or an object's "preset". `overrides` is set to
// an object block, whose other members change the preset.
struct NamedPreset {
  std::string name = "none";
  std::string pointer;
  const nlohmann::json* overrides = nullptr;
};

NamedPreset namedPreset(const std::optional<nlohmann::json>& block, const std::string& pointer, SettingErrors& errors) {
  NamedPreset named{.pointer = pointer};
  if (!block) return named;
  if (block->is_string()) {
    named.name = block->get<std::string>();
  } else if (block->is_object()) {
    named.overrides = &*block;
    if (auto it = block->find("preset"); it != block->end()) {
      named.pointer = appendPointer(pointer, "preset");
      if (!it->is_string()) errors.wrongKind(named.pointer, "setting 'preset'", "a preset's name", describeJsonKind(*it));
      else named.name = it->get<std::string>();
    } else {
      errors.report(DiagCode::WeatherPresetMissing, pointer, {presetList()});
    }
  }
  return named;
}

// "unknown weather effect 'x'", with the nearest names as its hint.
void reportUnknownEffect(DiagnosticList& diags, SourceLocation at, const std::string& name) {
  std::vector<std::string_view> names;
  for (const auto& f : kEffectFlags) names.push_back(f.name);
  diags.report(DiagCode::UnknownWeatherKey, std::move(at),
               {"effect", quoteUserText(name), unknownNameHint(name, names, "effects")});
}

// "effects": {"moss": false, ...}
void applyEffects(const nlohmann::json& value, const std::string& at, WeatherConfig& config, SettingErrors& errors) {
  if (!value.is_object()) {
    errors.wrongKind(at, "setting 'effects'", "an object of booleans, e.g. {\"moss\": false}", describeJsonKind(value));
    return;
  }
  for (const auto& [effect, on] : value.items()) {
    const WeatherEffectFlag* flag = findWeatherEffectFlag(effect);
    std::string effectAt = appendPointer(at, effect);
    if (!flag) {
      reportUnknownEffect(errors.diags, errors.doc.locate(effectAt), effect);
      errors.ok = false;
    } else if (!on.is_boolean()) {
      errors.wrongKind(effectAt, "effect '" + std::string(flag->name) + "'", "true or false", describeJsonKind(on));
    } else {
      config.effects.*(flag->flag) = on.get<bool>();
    }
  }
}

// What a value that is not four numbers is: "an array of 3", "an array holding a string"...
std::string describeFourNumbers(const nlohmann::json& value) {
  if (!value.is_array()) return describeJsonKind(value);
  if (value.size() != 4) return "an array of " + std::to_string(value.size());
  for (const auto& x : value)
    if (!x.is_number()) return "an array holding " + describeJsonKind(x);
  return describeJsonKind(value);
}

// "weights": [w1, w2, w3, w4] in [0, 16], or "terms": four 0 or 1; the first bad one stops.
void applyFourNumbers(const std::string& key, const nlohmann::json& value, const std::string& at, WeatherConfig& config,
                      SettingErrors& errors) {
  const bool weights = key == "weights";
  auto& target = weights ? config.weights : config.terms;
  bool shaped = value.is_array() && value.size() == 4 &&
                std::all_of(value.begin(), value.end(), [](const auto& x) { return x.is_number(); });
  if (!shaped) {
    errors.wrongKind(at, "setting '" + key + "'",
                     weights ? "an array of 4 numbers, [w1, w2, w3, w4]" : "an array of 4 switches, [inclination, sun, height, wind]",
                     describeFourNumbers(value));
    return;
  }
  for (std::size_t i = 0; i < 4; ++i) {
    float v = value[i].get<float>();
    bool inRange = weights ? (v >= 0.f && v <= 16.f) : (v == 0.f || v == 1.f);
    const std::string element = key + "[" + std::to_string(i) + "]";
    if (!inRange && weights) {
      errors.report(DiagCode::WeatherSettingOutOfRange, appendPointer(at, i), {element, formatFloat(v), "0", "16"});
      return;
    }
    if (!inRange) {
      errors.wrongKind(appendPointer(at, i), "setting '" + element + "'", "0 (off) or 1 (on)", formatFloat(v));
      return;
    }
    target[i] = v;
  }
}

// One of kNumberSettings, a finite number within its range.
void applyNumberSetting(const std::string& key, const nlohmann::json& value, const std::string& at,
                        WeatherConfig& config, SettingErrors& errors) {
  auto setting = std::find_if(kNumberSettings.begin(), kNumberSettings.end(),
                              [&key](const NumberSetting& s) { return s.name == key; });
  if (setting == kNumberSettings.end()) {
    std::vector<std::string_view> names = {"preset", "quality", "steep", "effects", "weights", "terms"};
    for (const auto& s : kNumberSettings) names.push_back(s.name);
    errors.report(DiagCode::UnknownWeatherKey, at, {"setting", quoteUserText(key), unknownNameHint(key, names, "settings")});
    return;
  }
  if (!value.is_number() || !std::isfinite(value.get<double>())) {
    errors.wrongKind(at, "setting '" + key + "'", "a finite number", describeJsonKind(value));
    return;
  }
  float v = value.get<float>();
  if (v < setting->min || v > setting->max) {
    errors.report(DiagCode::WeatherSettingOutOfRange, at,
                  {key, formatFloat(v), formatFloat(setting->min), formatFloat(setting->max)});
    return;
  }
  config.*(setting->field) = v;
}

// Every member of an object block but "preset" and "description", over the preset.
void applyOverrides(const nlohmann::json& overrides, const std::string& pointer, WeatherConfig& config,
                    SettingErrors& errors) {
  for (const auto& [key, value] : overrides.items()) {
    std::string at = appendPointer(pointer, key);
    if (key == "preset" || key == "description" || key == "quality" || key == "steep") continue;
    if (key == "effects") applyEffects(value, at, config, errors);
    else if (key == "weights" || key == "terms") applyFourNumbers(key, value, at, config, errors);
    else applyNumberSetting(key, value, at, config, errors);
  }
  if (config.minHeight >= config.maxHeight)
    errors.report(DiagCode::WeatherHeightRange, pointer, {formatFloat(config.minHeight), formatFloat(config.maxHeight)});
}

// Where only one of a slope blend's presets has moss, it fades with the slope. Terrain
// orientation (eq. 3.11-3.13) blends an object into the terrain under it, which a
// terrain's own cliffs do not need: the flat preset's setting stands.
constexpr std::string_view kSlopeFadedEffect = "moss";
constexpr std::string_view kFlatPresetsEffect = "terrainOrientation";

// "steep": {"preset": "rock", "slope": [30, 45]}: the steep preset's terms, and its
// effects switched on over the flat one's. An effect that only one of the two has must
// be one the slope can fade.
void applySteepBlend(const nlohmann::json& value, const std::string& at, WeatherConfig& config, SettingErrors& errors) {
  const std::string expected = "an object {\"preset\": NAME, \"slope\": [FROM, TO]} (degrees)";
  if (!value.is_object()) return errors.wrongKind(at, "setting 'steep'", expected, describeJsonKind(value));
  SteepBlend blend;
  for (const auto& [key, member] : value.items()) {
    const std::string memberAt = appendPointer(at, key);
    if (key == "preset") {
      if (!member.is_string()) return errors.wrongKind(memberAt, "setting 'steep.preset'", "a preset's name", describeJsonKind(member));
      blend.preset = member.get<std::string>();
    } else if (key == "slope") {
      const bool shaped = member.is_array() && member.size() == 2 && member[0].is_number() && member[1].is_number();
      if (!shaped) return errors.wrongKind(memberAt, "setting 'steep.slope'", "[FROM, TO] in degrees", describeJsonKind(member));
      blend.fromDegrees = member[0].get<float>();
      blend.toDegrees = member[1].get<float>();
      if (!(blend.fromDegrees >= 0.f && blend.fromDegrees < blend.toDegrees && blend.toDegrees <= 90.f))
        return errors.wrongKind(memberAt, "setting 'steep.slope'", "two angles with 0 <= FROM < TO <= 90",
                                "[" + formatFloat(blend.fromDegrees) + ", " + formatFloat(blend.toDegrees) + "]");
    } else if (key != "description") {
      return errors.report(DiagCode::UnknownWeatherKey, memberAt,
                           {"setting", quoteUserText(key), unknownNameHint(key, {"preset", "slope"}, "settings")});
    }
  }
  std::optional<WeatherConfig> steep = weatherPreset(blend.preset);
  if (!steep || !steep->active())
    return errors.wrongKind(appendPointer(at, "preset"), "setting 'steep.preset'", "a weathering preset (" + presetList() + " but none)",
                            quoteUserText(blend.preset));
  for (const WeatherEffectFlag& f : weatherEffectFlags()) {
    const bool flat = config.effects.*(f.flag), steepOn = steep->effects.*(f.flag);
    if (flat == steepOn || f.name == kFlatPresetsEffect) continue;
    if (f.name != kSlopeFadedEffect)
      return errors.wrongKind(appendPointer(at, "preset"), "setting 'steep.preset'",
                              "a preset with the same effects as '" + config.preset + "' but for moss and terrainOrientation",
                              "'" + blend.preset + "', which differs in " + std::string(f.name));
    config.effects.*(f.flag) = true;
  }
  blend.terms = steep->terms;
  config.steep = std::move(blend);
}

// The caller's effect switches, over the graph's, while the weather is active. An
// unknown name is an error either way; it has no place in the graph, so no location.
bool applyEffectOverrides(const WeatherEffectOverrides& overrides, WeatherConfig& config, DiagnosticList& diags) {
  bool ok = true;
  for (const auto& [name, on] : overrides) {
    if (const WeatherEffectFlag* flag = findWeatherEffectFlag(name)) {
      if (config.active()) config.effects.*(flag->flag) = on;
    } else {
      reportUnknownEffect(diags, SourceLocation{}, name);
      ok = false;
    }
  }
  return ok;
}

// "unknown weather quality tier 'x'", with the nearest names as its hint.
void reportUnknownTier(DiagnosticList& diags, SourceLocation at, const std::string& name) {
  std::vector<std::string_view> names;
  for (const QualityTier& t : qualityTiers()) names.push_back(t.name);
  diags.report(DiagCode::UnknownWeatherKey, std::move(at),
               {"quality tier", quoteUserText(name), unknownNameHint(name, names, "tiers")});
}

// The tier named `name`, or null after reporting it unknown at `at`.
const QualityTier* knownTier(const std::string& name, SourceLocation at, SettingErrors& errors) {
  const QualityTier* tier = findQualityTier(name);
  if (!tier) {
    reportUnknownTier(errors.diags, std::move(at), name);
    errors.ok = false;
  }
  return tier;
}

// The tier the caller asks for, else the block's "quality", else the fallback, over the
// preset's effects. False when a tier is unknown or the block's is not a string; the
// block's is checked even when the caller's replaces it, as its kind is.
bool applyQuality(const QualityChoice& quality, const nlohmann::json* block, const std::string& pointer,
                  WeatherConfig& config, SettingErrors& errors) {
  std::string name = quality.fallback;
  if (block && block->contains("quality")) {
    const std::string qualityAt = appendPointer(pointer, "quality");
    const nlohmann::json& value = block->at("quality");
    if (!value.is_string()) {
      errors.wrongKind(qualityAt, "setting 'quality'", "a tier's name (" + qualityTierList() + ")", describeJsonKind(value));
      return false;
    }
    name = value.get<std::string>();
    if (!knownTier(name, errors.doc.locate(qualityAt), errors)) return false;
  }
  if (quality.requested) name = *quality.requested;
  const QualityTier* tier = knownTier(name, SourceLocation{}, errors);
  if (!tier) return false;
  config.quality = tier->name;
  applyQualityTier(*tier, config.effects);
  return true;
}

}  // namespace

const std::array<WeatherEffectFlag, kWeatherEffectCount>& weatherEffectFlags() { return kEffectFlags; }

const WeatherEffectFlag* findWeatherEffectFlag(std::string_view name) {
  auto flag = std::find_if(kEffectFlags.begin(), kEffectFlags.end(),
                           [name](const WeatherEffectFlag& f) { return f.name == name; });
  return flag == kEffectFlags.end() ? nullptr : &*flag;
}

std::vector<std::string_view> weatherPresetNames() { return {kPresets.begin(), kPresets.end()}; }

std::optional<WeatherConfig> weatherPreset(std::string_view name) {
  if (std::find(kPresets.begin(), kPresets.end(), name) == kPresets.end()) return std::nullopt;
  return makePreset(std::string(name));
}

std::optional<WeatherConfig> resolveWeatherConfig(const std::optional<nlohmann::json>& block, const std::string& pointer,
                                                  const std::optional<std::string>& presetOverride,
                                                  const QualityChoice& quality,
                                                  const WeatherEffectOverrides& effectOverrides,
                                                  const JsonDocument& doc, DiagnosticList& diags) {
  SettingErrors errors{doc, diags};
  NamedPreset named = namedPreset(block, pointer, errors);
  auto reportUnknown = [&](const std::string& name, SourceLocation at) {
    diags.report(DiagCode::UnknownWeatherPreset, std::move(at),
                 {quoteUserText(name), unknownNameHint(name, weatherPresetNames(), "presets")});
  };
  // The graph's own preset is checked even when --weather-preset replaces it, as its
  // tier is: a file plain compile rejects is rejected whatever replaces its preset.
  if (presetOverride && block && !weatherPreset(named.name)) {
    reportUnknown(named.name, doc.locate(named.pointer));
    return std::nullopt;
  }
  if (presetOverride) named.name = *presetOverride;
  auto config = weatherPreset(named.name);
  if (!config) {
    reportUnknown(named.name, presetOverride ? SourceLocation{} : doc.locate(named.pointer));
    return std::nullopt;
  }
  // The blend belongs to the graph's own preset: --weather-preset replaces both.
  if (named.overrides && named.overrides->contains("steep") && !presetOverride)
    applySteepBlend(named.overrides->at("steep"), appendPointer(pointer, "steep"), *config, errors);
  if (!applyQuality(quality, named.overrides, pointer, *config, errors)) return std::nullopt;
  if (named.overrides) applyOverrides(*named.overrides, pointer, *config, errors);
  if (!applyEffectOverrides(effectOverrides, *config, diags)) return std::nullopt;
  if (config->active()) clearDeadEffects(config->effects);
  return errors.ok ? config : std::nullopt;
}

}  // namespace wg
