#include "compiler/quality_tiers.hpp"

#include <algorithm>
#include <array>

namespace wg {

namespace {

constexpr std::array<QualityTier, 3> kTiers = {{
    {"low", "seed 000's terms only: for GLSL ES and mobile GPUs", false, false, 180, 120},
    {"medium", "plus sky exposure: nothing under a roof or overhang gets snow, rain or puddles", true, false, 250, 120},
    {"high", "plus the looks: snow's and ice's relief, rain ripples, specular anti-aliasing", true, true, 320, 150},
}};

}  // namespace

std::span<const QualityTier> qualityTiers() { return kTiers; }

const QualityTier* findQualityTier(std::string_view name) {
  auto tier = std::find_if(kTiers.begin(), kTiers.end(), [name](const QualityTier& t) { return t.name == name; });
  return tier == kTiers.end() ? nullptr : &*tier;
}

int weatherBudget(const QualityTier& tier, ShaderStage stage) {
  return stage == ShaderStage::Vertex ? tier.vertexBudget : tier.fragmentBudget;
}

std::string qualityTierList() {
  std::string list;
  for (const QualityTier& t : kTiers) list += (list.empty() ? "" : ", ") + std::string(t.name);
  return list;
}

void applyQualityTier(const QualityTier& tier, WeatherEffects& effects) {
  effects.skyExposure = tier.skyExposure;
  effects.relief = effects.ripple = effects.specularAntiAliasing = tier.looks;
}

std::string chosenTierName(const QualityChoice& quality, const std::optional<nlohmann::json>& weatherBlock) {
  if (quality.requested) return *quality.requested;
  if (weatherBlock && weatherBlock->is_object())
    if (auto it = weatherBlock->find("quality"); it != weatherBlock->end() && it->is_string())
      if (const QualityTier* tier = findQualityTier(it->get<std::string>())) return std::string(tier->name);
  return quality.fallback;
}

std::vector<SwitchDecl> withQualityAxis(std::vector<SwitchDecl> declared, const std::string& defaultTier) {
  auto at = std::find_if(declared.begin(), declared.end(), [](const SwitchDecl& s) { return s.name >= kQualitySwitch; });
  if (at != declared.end() && at->name == kQualitySwitch) {
    if (std::find(at->values.begin(), at->values.end(), defaultTier) != at->values.end()) at->defaultValue = defaultTier;
    return declared;
  }
  SwitchDecl axis{std::string(kQualitySwitch), {}, defaultTier, ""};
  for (const QualityTier& t : kTiers) axis.values.emplace_back(t.name);
  declared.insert(at, std::move(axis));
  return declared;
}

void bindQualitySwitch(const MaterialGraph& graph, SwitchValues& switches, QualityChoice& quality) {
  auto own = std::find_if(graph.switches.begin(), graph.switches.end(),
                          [](const SwitchDecl& s) { return s.name == kQualitySwitch; });
  if (own == graph.switches.end()) return;
  const std::string key(kQualitySwitch);
  if (auto named = switches.find(key); named != switches.end()) {
    if (findQualityTier(named->second)) quality.requested = named->second;
    return;
  }
  std::string tier = chosenTierName(quality, graph.weather);
  if (std::find(own->values.begin(), own->values.end(), tier) != own->values.end()) switches[key] = tier;
}

}  // namespace wg
