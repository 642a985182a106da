// weathergen stats: what a material stats panel shows, per material, quality tier,
// stage and language: SPIR-V instructions after spirv-opt, what the weather adds to
// them (against the same graph with preset none), texture reads, branches, uniform
// bytes and interpolants. The budgets in docs/BENCHMARKS.md are read from it.
#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "cli/commands.hpp"
#include "cli/diagnostic_output.hpp"
#include "cli/option_table.hpp"
#include "compiler/literal.hpp"
#include "compiler/quality_tiers.hpp"
#include "driver/weather_cost.hpp"

namespace wg {

namespace {

constexpr const char* kStatsUsage = R"(Usage: weathergen stats GRAPH... [options]

For each material, quality tier, stage and language: SPIR-V instructions after
spirv-opt, the instructions the weather adds (against preset none at the same tier)
and the tier's budget for them, texture reads, conditional branches, uniform bytes
and interpolants, as a table or JSON.

Options:
)";

struct Options {
  std::vector<std::string> graphs;
  std::optional<std::string> quality;  // one tier; every tier when unset
  std::optional<std::string> weatherPreset;
  bool json = false;
  bool help = false;
};

std::string checkTierOrAll(const std::string& name) {
  if (name == "all" || findQualityTier(name)) return "";
  return "--quality: unknown tier '" + quoteUserText(name) + "' (tiers: " + qualityTierList() + ", or all)";
}

// --json anywhere on the line, read before the options: a usage error in front of it
// is JSON too.
bool jsonRequested(int argc, char** argv) {
  return std::any_of(argv + 2, argv + argc, [](const char* arg) { return std::string_view(arg) == "--json"; });
}

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
  std::string graph;  // the file, as given: two graphs may declare one material name
  std::string material, tier, stage, language;
  SpirvStatistics spirv;
  long weather = 0;  // instructions the weather adds
  int budget = 0;    // the tier's budget for the stage (GLSL; HLSL is held to the same)
  std::size_t uniformBytes = 0, interpolants = 0;
};

// Uniform bytes and interpolants, from the reflection both stages share.
std::pair<std::size_t, std::size_t> interfaceSizes(const CompiledMaterial& m) {
  const auto reflection = nlohmann::json::parse(m.reflectionJson);
  std::size_t uniformBytes = 0;
  for (const auto& block : reflection.at("blocks")) uniformBytes += block.at("size").get<std::size_t>();
  return {uniformBytes, reflection.at("varyings").size()};
}

// Every row of one graph, its diagnostics added to `diagnostics`; false when it does
// not compile.
bool graphRows(const std::string& graph, const Options& o, std::vector<StatsRow>& rows, DiagnosticList& diagnostics) {
  for (const QualityTier& tier : qualityTiers()) {
    if (o.quality && *o.quality != tier.name) continue;
    std::optional<WeatherCost> cost = weatherCostAtTier(graph, std::string(tier.name), o.weatherPreset, diagnostics);
    if (!cost) return false;
    const auto [uniformBytes, interpolants] = interfaceSizes(cost->material);
    for (const StageCost& s : cost->stages) {
      const bool vertex = s.stage == ShaderStage::Vertex;
      rows.push_back({graph, cost->material.name, std::string(tier.name), vertex ? "vert" : "frag",
                      std::string(languageName(s.language)), s.spirv, s.weather, weatherBudget(tier, s.stage),
                      uniformBytes, interpolants});
    }
  }
  return true;
}

// User text in a Markdown table cell: quoted, and a '|' escaped so that it cannot
// start a cell of its own.
std::string tableCell(const std::string& text) {
  std::string cell;
  for (char c : quoteUserText(text)) {
    if (c == '|') cell += '\\';
    cell += c;
  }
  return cell;
}

void printTable(const std::vector<StatsRow>& rows) {
  std::printf("| material | tier | stage | language | instructions | weather | budget | texture reads | branches | "
              "uniform bytes | interpolants |\n|---|---|---|---|---:|---:|---|---:|---:|---:|---:|\n");
  for (const StatsRow& r : rows)
    std::printf("| %s | %s | %s | %s | %zu | %+ld | %d%s | %zu | %zu | %zu | %zu |\n", tableCell(r.material).c_str(),
                r.tier.c_str(), r.stage.c_str(), r.language.c_str(), r.spirv.instructions, r.weather, r.budget,
                r.weather > r.budget ? " over" : "", r.spirv.textureReads, r.spirv.branches, r.uniformBytes,
                r.interpolants);
}

void printJson(const std::vector<StatsRow>& rows) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const StatsRow& r : rows)
    out.push_back({{"graph", r.graph}, {"material", r.material}, {"tier", r.tier}, {"stage", r.stage}, {"language", r.language},
                   {"instructions", r.spirv.instructions}, {"weatherInstructions", r.weather}, {"weatherBudget", r.budget},
                   {"textureReads", r.spirv.textureReads}, {"branches", r.spirv.branches},
                   {"uniformBytes", r.uniformBytes}, {"interpolants", r.interpolants}});
  // A path need not be UTF-8: its stray bytes become U+FFFD, as in the diagnostics.
  std::printf("%s\n", out.dump(2, ' ', false, nlohmann::json::error_handler_t::replace).c_str());
}

// Rows that did not reach stdout (a full disk, a closed descriptor) fail the command,
// as an output file that cannot be written fails compile.
int finishOutput(bool json) {
  if (std::fflush(stdout) == 0 && !std::ferror(stdout)) return kExitOk;
  return usageError(std::string("cannot write the rows to standard output: ") + std::strerror(errno), json);
}

}  // namespace

int runStatsCommand(int argc, char** argv) {
  Options o;
  const OptionTable table = statsOptionTable(o);
  const OptionParseResult parsed = parseOptions(table, argc, argv, 2);
  if (parsed.status == OptionParse::Failed) return usageError(parsed.error, jsonRequested(argc, argv));
  if (o.help) {
    std::printf("%s%s", kStatsUsage, formatOptionList(table).c_str());
    return kExitOk;
  }
  if (o.graphs.empty()) return usageError("stats needs at least one GRAPH.json", o.json);
  // Every graph's errors, not only the first graph's, and under --json one array on
  // stderr for the whole run.
  std::vector<StatsRow> rows;
  DiagnosticList diagnostics;
  bool compiled = true;
  for (const std::string& graph : o.graphs) compiled = graphRows(graph, o, rows, diagnostics) && compiled;
  printDiagnostics(diagnostics.items(), o.json);
  if (!compiled) return kExitBadInput;
  if (o.json) printJson(rows);
  else printTable(rows);
  return finishOutput(o.json);
}

}  // namespace wg
