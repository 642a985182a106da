#include "driver/weather_cost.hpp"

namespace wg {

namespace {

constexpr ShaderStage kStages[] = {ShaderStage::Vertex, ShaderStage::Fragment};
constexpr ShaderLanguage kLanguages[] = {ShaderLanguage::Glsl, ShaderLanguage::Hlsl};

std::optional<CompiledMaterial> compileAt(const std::string& graph, const std::string& tier,
                                          const std::optional<std::string>& preset, DiagnosticList& diagnostics) {
  CompileOptions options;
  options.weatherPreset = preset;
  options.quality.requested = tier;
  CompileResult result = compileMaterialFile(graph, options);
  diagnostics.append(result.diagnostics);
  return std::move(result.material);
}

}  // namespace

std::optional<WeatherCost> weatherCostAtTier(const std::string& graph, const std::string& tier,
                                             const std::optional<std::string>& preset, DiagnosticList& diagnostics) {
  std::optional<CompiledMaterial> none = compileAt(graph, tier, "none", diagnostics);
  if (!none) return std::nullopt;
  std::optional<CompiledMaterial> weathered = compileAt(graph, tier, preset, diagnostics);
  if (!weathered) return std::nullopt;
  WeatherCost cost{std::move(*weathered), std::move(*none), {}};
  for (ShaderStage stage : kStages)
    for (ShaderLanguage language : kLanguages) {
      StageCost s{stage, language, spirvStatistics(optimizeSpirv(cost.material.stage(language, stage).spirv))};
      const std::size_t bare = countInstructions(optimizeSpirv(cost.none.stage(language, stage).spirv));
      s.weather = static_cast<long>(s.spirv.instructions) - static_cast<long>(bare);
      cost.stages.push_back(s);
    }
  return cost;
}

}  // namespace wg
