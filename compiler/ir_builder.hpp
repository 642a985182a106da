// Stage 2: MaterialGraph -> IrGraph. Resolves ops, links, textures and parameters,
// infers types (the scalar splat is the only implicit conversion), detects cycles and
// checks literals. Reports every error it finds, not only the first.
#pragma once
#include <optional>

#include "compiler/diagnostic.hpp"
#include "compiler/ir.hpp"
#include "compiler/json_document.hpp"
#include "compiler/material_graph.hpp"
#include "compiler/quality_tiers.hpp"

namespace wg {

struct IrLimits {
  std::size_t maxNodes = 100000;  // ten times the largest synthetic benchmark graph
  // Longest link chain from an input to an output. Each level is one SSA statement that
  // drivers' shader compilers must schedule; hand-made materials stay under 100.
  std::size_t maxDepth = 4096;
};

struct IrBuildOptions {
  std::optional<std::string> weatherPreset;  // the CLI's --weather-preset, replacing the graph's
  WeatherEffectOverrides weatherEffects;    // the CLI's --effects, over the graph's own
  QualityChoice quality;                    // the CLI's --quality, else the graph's, else the targets' default
  IrLimits limits;
};

std::optional<IrGraph> buildIr(const MaterialGraph& graph, const JsonDocument& document,
                               DiagnosticList& diagnostics, const IrBuildOptions& options = {});

}  // namespace wg
