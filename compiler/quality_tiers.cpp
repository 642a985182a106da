#include "compiler/quality_tiers.hpp"

#include <algorithm>
#include <array>

namespace wg {

namespace {

constexpr std::array<QualityTier, 3> kTiers = {{
    {"low", "seed 000's terms only: for GLSL ES and mobile GPUs", false, false},
    {"medium", "plus sky exposure: nothing under a roof or overhang gets snow, rain or puddles", true, false},
    {"high", "plus the looks: snow's and ice's relief, rain ripples, specular anti-aliasing", true, true},
}};

}  // namespace

std::span<const QualityTier> qualityTiers() { return kTiers; }

const QualityTier* findQualityTier(std::string_view name) {
  auto tier = std::find_if(kTiers.begin(), kTiers.end(), [name](const QualityTier& t) { return t.name == name; });
  return tier == kTiers.end() ? nullptr : &*tier;
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

}  // namespace wg
