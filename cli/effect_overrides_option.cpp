#include "cli/effect_overrides_option.hpp"

#include <algorithm>

#include "compiler/literal.hpp"
#include "compiler/quality_tiers.hpp"

namespace wg {

namespace {

constexpr std::string_view kForm = "--effects takes NAME=on|off[,NAME=on|off...], e.g. specularAntiAliasing=off";

std::string effectNameList() {
  std::string names;
  for (const auto& f : weatherEffectFlags()) names += (names.empty() ? "" : ", ") + std::string(f.name);
  return names;
}

// One NAME=on|off item: "" or the message.
std::string addEffectOverride(std::string_view item, WeatherEffectOverrides& effects) {
  const std::size_t equals = item.find('=');
  if (equals == std::string_view::npos) return std::string(kForm) + "; '" + quoteUserText(item) + "' has no '='";
  const std::string name(item.substr(0, equals));
  const std::string_view value = item.substr(equals + 1);
  if (!findWeatherEffectFlag(name))
    return "--effects: unknown effect '" + quoteUserText(name) + "' (effects: " + effectNameList() + ")";
  if (std::any_of(effects.begin(), effects.end(), [&name](const auto& e) { return e.first == name; }))
    return "--effects names '" + name + "' twice; give each effect once";
  if (value != "on" && value != "off")
    return "--effects: " + name + " takes on or off, not '" + quoteUserText(value) + "'";
  effects.emplace_back(name, value == "on");
  return "";
}

}  // namespace

std::string addEffectOverrides(const std::string& text, WeatherEffectOverrides& effects) {
  if (text.empty()) return std::string(kForm);
  std::string_view rest = text;
  while (true) {
    const std::size_t comma = rest.find(',');
    if (std::string e = addEffectOverride(rest.substr(0, comma), effects); !e.empty()) return e;
    if (comma == std::string_view::npos) return "";
    rest.remove_prefix(comma + 1);
  }
}

std::string checkQualityTierName(const std::string& name) {
  if (findQualityTier(name)) return "";
  return "--quality: unknown tier '" + quoteUserText(name) + "' (tiers: " + qualityTierList() + ")";
}

std::string effectOverridesText(const WeatherEffectOverrides& effects) {
  std::string text;
  for (const auto& [name, on] : effects) text += (text.empty() ? "" : ", ") + name + (on ? "=on" : "=off");
  return text;
}

}  // namespace wg
