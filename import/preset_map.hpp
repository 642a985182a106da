// Which weather preset each imported material gets: one preset for all, or
// --preset-map 'GLOB=PRESET,...' rules matched against material names in order
// (shell globs: * ? [...]); a material no rule matches gets no weather.
#pragma once
#include <optional>
#include <string>
#include <vector>

namespace wg::gltf {

struct PresetRule {
  std::string glob, preset;
};

class PresetChoice {
 public:
  static PresetChoice everywhere(std::string preset);
  // Parses RULES; on failure returns nullopt with a one-line `error` (user text quoted).
  static std::optional<PresetChoice> fromMap(const std::string& rules, std::string& error);

  std::string presetFor(const std::string& materialName) const;

 private:
  std::vector<PresetRule> rules_;
};

}  // namespace wg::gltf
