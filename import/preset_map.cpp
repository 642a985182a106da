#include "import/preset_map.hpp"

#include <fnmatch.h>

#include "compiler/literal.hpp"
#include "compiler/weather_config.hpp"

namespace wg::gltf {

PresetChoice PresetChoice::everywhere(std::string preset) {
  PresetChoice c;
  c.rules_.push_back({"*", std::move(preset)});
  return c;
}

std::optional<PresetChoice> PresetChoice::fromMap(const std::string& rules, std::string& error) {
  PresetChoice c;
  std::size_t start = 0;
  while (start <= rules.size()) {
    std::size_t comma = rules.find(',', start);
    std::string rule = rules.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    std::size_t eq = rule.rfind('=');
    if (eq == std::string::npos || eq == 0) {
      error = "--preset-map rule '" + quoteUserText(rule) + "' is not GLOB=PRESET (e.g. '*Leaf*=foliage,*=rock')";
      return std::nullopt;
    }
    std::string preset = rule.substr(eq + 1);
    if (!weatherPreset(preset)) {
      std::string names;
      for (auto n : weatherPresetNames()) names += (names.empty() ? "" : ", ") + std::string(n);
      error = "--preset-map rule '" + quoteUserText(rule) + "' names no weather preset (presets: " + names + ")";
      return std::nullopt;
    }
    c.rules_.push_back({rule.substr(0, eq), preset});
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return c;
}

std::string PresetChoice::presetFor(const std::string& materialName) const {
  for (const auto& r : rules_)
    if (::fnmatch(r.glob.c_str(), materialName.c_str(), 0) == 0) return r.preset;
  return "none";
}

}  // namespace wg::gltf
