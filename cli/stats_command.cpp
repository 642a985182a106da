// weathergen stats: what a material stats panel shows, per material, quality tier,
// stage and language: SPIR-V instructions after spirv-opt, what the weather adds to
// them (against the same graph with preset none), texture reads, branches, uniform
// bytes and interpolants. The budgets in docs/BENCHMARKS.md are read from it.
#include <cstdio>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cli/diagnostic_output.hpp"
#include "cli/effect_overrides_option.hpp"
#include "cli/option_table.hpp"
#include "compiler/literal.hpp"
#include "compiler/quality_tiers.hpp"
#include "driver/material_compiler.hpp"

namespace wg {

namespace {

constexpr const char* kStatsUsage = R"(Usage: weathergen stats GRAPH... [options]

For each material, quality tier, stage and language: SPIR-V instructions after
spirv-opt, the instructions the weather adds (against preset none), texture reads,
conditional branches, uniform bytes and interpolants, as a table or JSON.

Options:
)";

struct Options {
  std::vector<std::string> graphs;
  std::optional<std::string> quality;  // one tier; every tier when unset
  std::optional<std::string> weatherPreset;
  bool json = false;
  bool help = false;
};

std::string checkTierOrAll(const std::string& name) { return name == "all" ? "" : checkQualityTierName(name); }

OptionTable statsOptionTable(Options& o) {
  return {.options = {
              {"--quality", "", "TIER|all", "one quality tier (low, medium, high), or all (default)",
               [&o](const std::string& v) {
                 if (std::string e = checkTierOrAll(v); !e.empty()) return e;
                 if (v != "all") o.quality = v;
                 return std::string();
               }},
              {"--weather-preset", "", "NAME", "weather preset, replacing each graph's own",
               storeChecked(o.weatherPreset, checkWeatherPresetName)},
              {"--json", "", "", "one JSON array of rows on stdout instead of a table", storeFlag(o.json)},
              {"--help", "-h", "", "this help", storeFlag(o.help), true},
          },
          .operand = [&o](const std::string& graph) {
            o.graphs.push_back(graph);
            return std::string();
          }};
}

struct StatsRow {
  std::string material, tier, stage, language;
  SpirvStatistics spirv;
  long weather = 0;  // instructions the weather adds
  std::size_t uniformBytes = 0, interpolants = 0;
};

// Uniform bytes and interpolants, from the reflection both stages share.
std::pair<std::size_t, std::size_t> interfaceSizes(const CompiledMaterial& m) {
  const auto reflection = nlohmann::json::parse(m.reflectionJson);
  std::size_t uniformBytes = 0;
  for (const auto& block : reflection.at("blocks")) uniformBytes += block.at("size").get<std::size_t>();
  return {uniformBytes, reflection.at("varyings").size()};
}

constexpr ShaderStage kStages[] = {ShaderStage::Vertex, ShaderStage::Fragment};
constexpr ShaderLanguage kLanguages[] = {ShaderLanguage::Glsl, ShaderLanguage::Hlsl};

std::optional<CompiledMaterial> compileForStats(const std::string& graph, const Options& o,
                                                const std::optional<std::string>& preset,
                                                const std::optional<std::string>& tier) {
  CompileOptions options;
  options.weatherPreset = preset;
  options.quality.requested = tier;
  CompileResult result = compileMaterialFile(graph, options);
  printDiagnostics(result.diagnostics.items(), o.json);
  return std::move(result.material);
}

// Every row of one graph; false when it does not compile.
bool graphRows(const std::string& graph, const Options& o, std::vector<StatsRow>& rows) {
  std::vector<std::string> tiers;
  for (const QualityTier& t : qualityTiers())
    if (!o.quality || *o.quality == t.name) tiers.emplace_back(t.name);
  for (const std::string& tier : tiers) {
    // Against preset none at the same tier: a graph's own "quality" switch follows the
    // tier, and what it drops from the material is not the weather's.
    const std::optional<CompiledMaterial> none = compileForStats(graph, o, "none", tier);
    if (!none) return false;
    std::map<std::pair<ShaderStage, ShaderLanguage>, std::size_t> bare;
    for (ShaderStage stage : kStages)
      for (ShaderLanguage language : kLanguages)
        bare[{stage, language}] = countInstructions(optimizeSpirv(none->stage(language, stage).spirv));
    const std::optional<CompiledMaterial> m = compileForStats(graph, o, o.weatherPreset, tier);
    if (!m) return false;
    const auto [uniformBytes, interpolants] = interfaceSizes(*m);
    for (ShaderStage stage : kStages)
      for (ShaderLanguage language : kLanguages) {
        StatsRow row{m->name, tier, stage == ShaderStage::Vertex ? "vert" : "frag", std::string(languageName(language))};
        row.spirv = spirvStatistics(optimizeSpirv(m->stage(language, stage).spirv));
        row.weather = static_cast<long>(row.spirv.instructions) - static_cast<long>(bare.at({stage, language}));
        row.uniformBytes = uniformBytes;
        row.interpolants = interpolants;
        rows.push_back(std::move(row));
      }
  }
  return true;
}

void printTable(const std::vector<StatsRow>& rows) {
  std::printf("| material | tier | stage | language | instructions | weather | texture reads | branches | uniform bytes | "
              "interpolants |\n|---|---|---|---|---:|---:|---:|---:|---:|---:|\n");
  for (const StatsRow& r : rows)
    std::printf("| %s | %s | %s | %s | %zu | %+ld | %zu | %zu | %zu | %zu |\n", quoteUserText(r.material).c_str(),
                r.tier.c_str(), r.stage.c_str(), r.language.c_str(), r.spirv.instructions, r.weather,
                r.spirv.textureReads, r.spirv.branches, r.uniformBytes, r.interpolants);
}

void printJson(const std::vector<StatsRow>& rows) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const StatsRow& r : rows)
    out.push_back({{"material", r.material}, {"tier", r.tier}, {"stage", r.stage}, {"language", r.language},
                   {"instructions", r.spirv.instructions}, {"weatherInstructions", r.weather},
                   {"textureReads", r.spirv.textureReads}, {"branches", r.spirv.branches},
                   {"uniformBytes", r.uniformBytes}, {"interpolants", r.interpolants}});
  std::printf("%s\n", out.dump(2).c_str());
}

}  // namespace

int runStatsCommand(int argc, char** argv) {
  Options o;
  const OptionTable table = statsOptionTable(o);
  const OptionParseResult parsed = parseOptions(table, argc, argv, 2);
  if (parsed.status == OptionParse::Failed) return usageError(parsed.error, o.json);
  if (o.help) {
    std::printf("%s%s", kStatsUsage, formatOptionList(table).c_str());
    return kExitOk;
  }
  if (o.graphs.empty()) return usageError("stats needs at least one GRAPH.json", o.json);
  std::vector<StatsRow> rows;
  for (const std::string& graph : o.graphs)
    if (!graphRows(graph, o, rows)) return kExitBadInput;
  if (o.json) printJson(rows);
  else printTable(rows);
  return kExitOk;
}

}  // namespace wg
