// `--effects NAME=on|off,...` (compile, render, bench-render, eval): weather effects
// switched over every graph's own "effects" block, by the names that block takes.
#pragma once
#include <string>
#include <string_view>

#include "compiler/weather_config.hpp"

namespace wg {

// The option's help lines, shared by every command that takes it.
inline constexpr std::string_view kEffectsOptionHelp =
    "switch weather effects over every graph's own: NAME=on|off,\n"
    "NAME as in a graph's \"effects\" block (e.g. relief=off,\n"
    "specularAntiAliasing=off); graphs without weather ignore it";

inline constexpr std::string_view kQualityOptionHelp =
    "quality tier for every graph: low (seed 000's terms), medium\n"
    "(plus sky exposure) or high (plus the looks); over the\n"
    "graph's own; default high (low when every target is\n"
    "glsles or msl). --effects still switches effects after it";

// "" for a tier's name, else a one-line message listing the tiers.
std::string checkQualityTierName(const std::string& name);

// Appends the effects the text names to `effects`; returns "" or a one-line usage
// message (an unknown name lists the names, a name given twice is refused).
std::string addEffectOverrides(const std::string& text, WeatherEffectOverrides& effects);

// "relief=off, ripple=off": what a report prints of them; "" for none.
std::string effectOverridesText(const WeatherEffectOverrides& effects);

}  // namespace wg
