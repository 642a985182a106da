// weathergen stats: what a material stats panel shows, per material, quality tier,
// stage and language: SPIR-V instructions after spirv-opt, what the weather adds to
// them (against the same graph with preset none), texture reads, branches, uniform
// bytes and interpolants. The budgets in docs/BENCHMARKS.md are read from it.
#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "cli/commands.hpp"
#include "cli/diagnostic_output.hpp"
#include "cli/option_table.hpp"
#include "compiler/json_text.hpp"
#include "compiler/literal.hpp"
#include "compiler/quality_tiers.hpp"
#include "driver/weather_cost.hpp"
#include "host/gpu_shader_statistics.hpp"

namespace wg {

namespace {

constexpr const char* kStatsUsage = R"(Usage: weathergen stats GRAPH... [options]

For each material, quality tier, stage and language: SPIR-V instructions after
spirv-opt, the instructions the weather adds (against preset none at the same tier)
and the tier's budget for them, texture reads, conditional branches, uniform bytes
and interpolants, as a table or JSON. With --gpu, each GLSL row also shows what an
AMD GPU's own compiler (ACO, through Mesa RADV's null device: no GPU needed) makes of
the stage in the lit pipeline: vector registers, waves per SIMD, ISA instructions and
the ISA instructions the weather adds.

Options:
)";

struct Options {
  std::vector<std::string> graphs;
  std::optional<std::string> quality;  // one tier; every tier when unset
  std::optional<std::string> weatherPreset;
  std::optional<std::string> gpuFamily;
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
              {"--gpu", "", "FAMILY", "AMD GPU family to compile GLSL rows for: navi21 (RDNA2),\n"
               "gfx1100 (RDNA3), navi10 (RDNA1), vega10 (GCN 5)...",
               [&o](const std::string& v) {
                 o.gpuFamily = v;
                 return v.empty() ? std::string("--gpu takes an AMD GPU family, e.g. navi21") : std::string();
               }},
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
  // --gpu, GLSL rows: the stage in the lit pipeline, weathered, and the ISA instructions
  // the weather adds against preset none.
  std::optional<ExecutableStatistics> gpu;
  long gpuWeatherInstructions = 0;
};

double statistic(const ExecutableStatistics& s, const char* name) {
  auto it = s.find(name);
  return it == s.end() ? 0 : it->second;
}
long long count(const ExecutableStatistics& s, const char* name) { return std::llround(statistic(s, name)); }

// The GPU's figures for each GLSL row of one tier's cost.
void addGpuStatistics(GpuShaderCompiler& gpu, const WeatherCost& cost, std::vector<StatsRow>& rows, std::size_t first) {
  auto glsl = [](const CompiledMaterial& m, ShaderStage stage) -> const SpirvWords& {
    return m.stage(ShaderLanguage::Glsl, stage).spirv;
  };
  const StageGpuStatistics weathered = gpu.litPipeline(cost.material.reflectionJson, glsl(cost.material, ShaderStage::Vertex),
                                                       glsl(cost.material, ShaderStage::Fragment));
  const StageGpuStatistics none =
      gpu.litPipeline(cost.none.reflectionJson, glsl(cost.none, ShaderStage::Vertex), glsl(cost.none, ShaderStage::Fragment));
  for (std::size_t i = first; i < rows.size(); ++i) {
    StatsRow& r = rows[i];
    if (r.language != "glsl") continue;
    const bool vertex = r.stage == "vert";
    r.gpu = vertex ? weathered.vertex : weathered.fragment;
    r.gpuWeatherInstructions = static_cast<long>(statistic(*r.gpu, "Instructions")) -
                               static_cast<long>(statistic(vertex ? none.vertex : none.fragment, "Instructions"));
  }
}

// Uniform bytes and interpolants, from the reflection both stages share.
std::pair<std::size_t, std::size_t> interfaceSizes(const CompiledMaterial& m) {
  const auto reflection = nlohmann::json::parse(m.reflectionJson);
  std::size_t uniformBytes = 0;
  for (const auto& block : reflection.at("blocks")) uniformBytes += block.at("size").get<std::size_t>();
  return {uniformBytes, reflection.at("varyings").size()};
}

// Every row of one graph, its diagnostics added to `diagnostics`; false when it does
// not compile.
bool graphRows(const std::string& graph, const Options& o, GpuShaderCompiler* gpu, std::vector<StatsRow>& rows,
               DiagnosticList& diagnostics) {
  for (const QualityTier& tier : qualityTiers()) {
    if (o.quality && *o.quality != tier.name) continue;
    std::optional<WeatherCost> cost = weatherCostAtTier(graph, std::string(tier.name), o.weatherPreset, diagnostics);
    if (!cost) return false;
    const std::size_t first = rows.size();
    const auto [uniformBytes, interpolants] = interfaceSizes(cost->material);
    for (const StageCost& s : cost->stages) {
      const bool vertex = s.stage == ShaderStage::Vertex;
      rows.push_back({graph, cost->material.name, std::string(tier.name), vertex ? "vert" : "frag",
                      std::string(languageName(s.language)), s.spirv, s.weather, weatherBudget(tier, s.stage),
                      uniformBytes, interpolants});
    }
    if (gpu) addGpuStatistics(*gpu, *cost, rows, first);
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

// "| VGPRs | waves | ISA | weather ISA" for a --gpu row, dashes for one without (HLSL).
std::string gpuCells(const StatsRow& r) {
  if (!r.gpu) return " - | - | - | - |";
  char cells[96];
  std::snprintf(cells, sizeof cells, " %.0f | %.0f | %.0f | %+ld |", statistic(*r.gpu, "VGPRs"),
                statistic(*r.gpu, "Subgroups per SIMD"), statistic(*r.gpu, "Instructions"), r.gpuWeatherInstructions);
  return cells;
}

// Each file once: a graph given twice, under any spelling of its path, adds no rows.
// Files are told apart by device and inode, one stat each; a path that cannot be
// stat'ed is told apart by its text (it is reported as unreadable).
std::vector<std::string> distinctGraphs(const std::vector<std::string>& graphs) {
  std::vector<std::string> distinct;
  std::set<std::pair<dev_t, ino_t>> files;
  std::set<std::string> unreadable;
  for (const std::string& graph : graphs) {
    struct stat status {};
    const bool added = ::stat(graph.c_str(), &status) == 0 ? files.insert({status.st_dev, status.st_ino}).second
                                                          : unreadable.insert(graph).second;
    if (added) distinct.push_back(graph);
  }
  return distinct;
}

// Material names that more than one graph declares: their rows name the file as well.
std::set<std::string> sharedMaterialNames(const std::vector<StatsRow>& rows) {
  std::map<std::string, std::string> firstGraph;
  std::set<std::string> shared;
  for (const StatsRow& r : rows)
    if (auto [at, added] = firstGraph.emplace(r.material, r.graph); !added && at->second != r.graph) shared.insert(r.material);
  return shared;
}

void printTable(const std::vector<StatsRow>& rows, bool gpu) {
  std::printf("| material | tier | stage | language | instructions | weather | budget | texture reads | branches | "
              "uniform bytes | interpolants |%s\n|---|---|---|---|---:|---:|---|---:|---:|---:|---:|%s\n",
              gpu ? " VGPRs | waves per SIMD | ISA instructions | weather ISA |" : "", gpu ? "---:|---:|---:|---:|" : "");
  const std::set<std::string> shared = sharedMaterialNames(rows);
  for (const StatsRow& r : rows)
    std::printf("| %s | %s | %s | %s | %zu | %+ld | %d%s | %zu | %zu | %zu | %zu |%s\n",
                tableCell(shared.count(r.material) ? r.material + " (" + r.graph + ")" : r.material).c_str(),
                r.tier.c_str(), r.stage.c_str(), r.language.c_str(), r.spirv.instructions, r.weather, r.budget,
                r.weather > r.budget ? " over" : "", r.spirv.textureReads, r.spirv.branches, r.uniformBytes,
                r.interpolants, gpu ? gpuCells(r).c_str() : "");
}

void printJson(const std::vector<StatsRow>& rows) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const StatsRow& r : rows)
    out.push_back({{"graph", r.graph}, {"material", r.material}, {"tier", r.tier}, {"stage", r.stage}, {"language", r.language},
                   {"instructions", r.spirv.instructions}, {"weatherInstructions", r.weather}, {"weatherBudget", r.budget},
                   {"textureReads", r.spirv.textureReads}, {"branches", r.spirv.branches},
                   {"uniformBytes", r.uniformBytes}, {"interpolants", r.interpolants}});
  for (std::size_t i = 0; i < rows.size(); ++i)
    if (const StatsRow& r = rows[i]; r.gpu)
      out[i]["gpu"] = {{"vgprs", count(*r.gpu, "VGPRs")}, {"sgprs", count(*r.gpu, "SGPRs")},
                       {"wavesPerSimd", count(*r.gpu, "Subgroups per SIMD")},
                       {"instructions", count(*r.gpu, "Instructions")},
                       {"weatherInstructions", r.gpuWeatherInstructions}, {"codeBytes", count(*r.gpu, "Code size")}};
  // A path need not be UTF-8: its stray bytes become U+FFFD, as in the diagnostics.
  std::printf("%s\n", jsonText(out, 2).c_str());
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
  std::unique_ptr<GpuShaderCompiler> gpu;
  if (o.gpuFamily) {
    std::string error;
    gpu = GpuShaderCompiler::forAmdFamily(*o.gpuFamily, error);
    if (!gpu) return usageError("--gpu '" + quoteUserText(*o.gpuFamily) + "': " + error, o.json);
  }
  std::vector<StatsRow> rows;
  DiagnosticList diagnostics;
  bool compiled = true;
  for (const std::string& graph : distinctGraphs(o.graphs)) compiled = graphRows(graph, o, gpu.get(), rows, diagnostics) && compiled;
  printDiagnostics(diagnostics.items(), o.json);
  if (!compiled) return kExitBadInput;
  if (o.json) printJson(rows);
  else printTable(rows, gpu != nullptr);
  return finishOutput(o.json);
}

}  // namespace wg
