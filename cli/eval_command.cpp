// weathergen eval: one material at one surface point on the CPU, printed as JSON.
// The graph is built exactly as 'compile' builds it (same passes, same weather
// injection), then every node runs through its op's CPU function.
#include <charconv>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cli/diagnostic_output.hpp"
#include "cli/effect_overrides_option.hpp"
#include "cli/eval_inputs.hpp"
#include "cli/option_table.hpp"
#include "compiler/content_hash.hpp"
#include "compiler/graph_loader.hpp"
#include "compiler/json_text.hpp"
#include "compiler/literal.hpp"
#include "driver/material_compiler.hpp"
#include "compiler/texture_loading.hpp"

namespace wg {

namespace {

using Json = nlohmann::ordered_json;

constexpr const char* kEvalUsage = R"(Usage: weathergen eval GRAPH [options]

Evaluates the material at one surface point on the CPU, with the op functions the
shaders mirror, and prints JSON: the inputs used, every PBR output and every weather
coverage term.

Options:
)";
constexpr const char* kEvalUsageEnd = R"(
Vectors are written with ':' between components: normal=0:1:0, windDirection=1:0
(world x:z). Each option may be repeated; each key may be given once.
)";

// Column where --help starts an input's description.
constexpr int kHelpNameWidth = 32;
constexpr int kJsonIndent = 2;

struct Options {
  std::vector<std::string> graphs;  // one, checked after parsing
  std::string graph;
  std::optional<std::string> weatherPreset;
  std::optional<std::string> quality;
  WeatherEffectOverrides effects;
  std::vector<std::pair<std::string, std::string>> lists;  // flag, "name=value,..." in order
  bool help = false;
  bool json = false;
};

// --weather, --at and --param keep their order and their flag: applied after the graph is read.
OptionSetter storeList(Options& o, std::string_view flag) {
  return [&o, flag](const std::string& v) {
    o.lists.emplace_back(flag, v);
    return std::string();
  };
}

OptionTable evalOptionTable(Options& o) {
  return {.options = {
              {"--weather-preset", "", "NAME",
               "weather preset, replacing the graph's own\n(rock, terrain, foliage, river, road, none)",
               storeChecked(o.weatherPreset, checkWeatherPresetName)},
              {"--quality", "", "TIER", kQualityOptionHelp, storeChecked(o.quality, checkQualityTierName)},
              {"--effects", "", "LIST", kEffectsOptionHelp,
               [&o](const std::string& v) { return addEffectOverrides(v, o.effects); }},
              {"--weather", "", "name=value,...", "frame block weather members (below)", storeList(o, "--weather")},
              {"--at", "", "name=value,...", "surface inputs at the point (below)", storeList(o, "--at")},
              {"--param", "", "name=value,...", "material parameters (with GRAPH, --help lists them)",
               storeList(o, "--param")},
              {"--diagnostics", "", "text|json", "diagnostic format on stderr (default: text)",
               [&o](const std::string& v) { return setDiagnosticsFormat(v, o.json); }},
              {"--help", "-h", "", "this help; with GRAPH, also the material's parameters", storeFlag(o.help)},
          },
          .operand = [&o](const std::string& graph) {
            o.graphs.push_back(graph);
            return std::string();
          },
          .unknownSuffix = "; run 'weathergen eval --help' for the options"};
}

std::string evalUsage() {
  Options scratch;  // the listing reads only the rows' names and help
  return kEvalUsage + formatOptionList(evalOptionTable(scratch)) + kEvalUsageEnd;
}

// A float as the JSON number of its shortest round-trip text, so 0.3f prints as 0.3
// rather than as the double 0.30000001192092896.
Json number(float x) {
  if (!std::isfinite(x)) return nullptr;
  const std::string text = formatFloat(x);
  double d = 0.0;
  std::from_chars(text.data(), text.data() + text.size(), d);
  return d;
}

Json components(std::span<const float> values) {
  if (values.size() == 1) return number(values[0]);
  Json out = Json::array();
  for (float x : values) out.push_back(number(x));
  return out;
}

Json valueJson(const Value& v) {
  if (v.type == ValueType::Bool) return v.asBool();
  return components(std::span<const float>(v.v.data(), static_cast<std::size_t>(v.width())));
}

std::string valueText(const Value& v) {
  if (v.type == ValueType::Bool) return v.asBool() ? "true" : "false";
  return formatComponents(std::span<const float>(v.v.data(), static_cast<std::size_t>(v.width())));
}

void printHelp(const IrGraph* graph) {
  std::fputs(evalUsage().c_str(), stdout);
  EvalInputs defaults = defaultEvalInputs();
  for (EvalInputGroup group : {EvalInputGroup::Weather, EvalInputGroup::Surface}) {
    std::printf("\n%s inputs (%s), with their defaults:\n", group == EvalInputGroup::Weather ? "Weather" : "Surface",
                std::string(evalInputFlag(group)).c_str());
    for (const auto& spec : evalInputSpecs()) {
      if (spec.group != group) continue;
      std::string entry = std::string(spec.name) + "=" + formatComponents(spec.field(defaults));
      std::printf("  %-*s %s\n", kHelpNameWidth, entry.c_str(), std::string(spec.doc).c_str());
    }
  }
  if (!graph) {
    std::printf("\nRun 'weathergen eval GRAPH --help' to list a material's parameters (--param).\n");
    return;
  }
  std::printf("\nParameters of material '%s' (--param), with their defaults:\n", quoteUserText(graph->name).c_str());
  for (const auto& p : graph->parameters) {
    std::string entry = quoteUserText(p.name) + "=" + valueText(p.defaultValue);
    std::string about = std::string(typeName(p.type));
    if (p.min || p.max)
      about += " in [" + (p.min ? formatNumber(*p.min) : "-inf") + ", " + (p.max ? formatNumber(*p.max) : "inf") + "]";
    if (!p.label.empty()) about += "  " + quoteUserText(p.label);
    std::printf("  %-*s %s\n", kHelpNameWidth, entry.c_str(), about.c_str());
  }
}

// Parses the command line; returns an exit code when it should stop (help is left to
// the caller, which may need the graph first).
std::optional<int> parseEvalOptions(int argc, char** argv, Options& o) {
  o.json = jsonDiagnosticsRequested(argc, argv, 2);
  const OptionParseResult parsed = parseOptions(evalOptionTable(o), argc, argv, 2);
  if (parsed.status == OptionParse::Failed) return usageError(parsed.error, o.json);
  if (o.graphs.size() > 1) return usageError("eval takes one graph, got " + std::to_string(o.graphs.size()), o.json);
  if (o.graphs.empty() && !o.help) return usageError("no input graph; write 'weathergen eval GRAPH'", o.json);
  if (!o.graphs.empty()) o.graph = o.graphs.front();
  return std::nullopt;
}

// Objects one member a line and arrays on one line ("baseColor": [0.5, 0.4, 0.3]), so
// vectors read as vectors.
void writeJson(std::string& out, const Json& value, int depth) {
  auto dump = [](const Json& j) { return jsonText(j); };
  if (value.is_object() && !value.empty()) {
    out += "{";
    const char* separator = "\n";
    for (auto it = value.begin(); it != value.end(); ++it) {
      out += separator + std::string(static_cast<std::size_t>((depth + 1) * kJsonIndent), ' ') + dump(it.key()) + ": ";
      writeJson(out, it.value(), depth + 1);
      separator = ",\n";
    }
    out += "\n" + std::string(static_cast<std::size_t>(depth * kJsonIndent), ' ') + "}";
  } else if (value.is_array()) {
    out += "[";
    for (std::size_t i = 0; i < value.size(); ++i) out += (i ? ", " : "") + dump(value[i]);
    out += "]";
  } else {
    out += dump(value);
  }
}

Json inputsJson(const EvalInputs& used, const IrGraph& graph) {
  Json weather = Json::object(), surface = Json::object(), parameters = Json::object();
  EvalInputs copy = used;  // the spec's accessors take a mutable reference
  for (const auto& spec : evalInputSpecs())
    (spec.group == EvalInputGroup::Weather ? weather : surface)[std::string(spec.name)] = components(spec.field(copy));
  for (const auto& p : graph.parameters) {
    auto it = used.parameters.find(p.name);
    parameters[p.name] = valueJson(it != used.parameters.end() ? it->second : p.defaultValue);
  }
  return {{"weather", std::move(weather)}, {"surface", std::move(surface)}, {"parameters", std::move(parameters)}};
}

// The graph built as compile builds it; nullopt when it has errors (printed).
std::optional<IrGraph> buildEvalGraph(const Options& o) {
  DiagnosticList diagnostics;
  std::optional<IrGraph> ir;
  if (auto text = readGraphFile(o.graph, diagnostics))
    ir = buildOptimizedIr(o.graph, std::move(*text), diagnostics,
                          CompileOptions{.weatherPreset = o.weatherPreset, .weatherEffects = o.effects,
                                         .quality = {.requested = o.quality}});
  if (!diagnostics.empty()) printDiagnostics(diagnostics.items(), o.json);
  if (!ir || diagnostics.hasErrors()) return std::nullopt;
  return ir;
}

// The defaults with every --weather, --at and --param applied in order; "" or the usage message.
std::string applyInputLists(const Options& o, const IrGraph& ir, EvalInputs& inputs) {
  std::set<std::string> seenWeather, seenSurface, seenParameters;
  for (const auto& [flag, list] : o.lists) {
    std::string error = flag == "--param"     ? applyParameterList(list, ir, inputs, seenParameters)
                        : flag == "--weather" ? applyEvalInputList(list, EvalInputGroup::Weather, inputs, seenWeather)
                                              : applyEvalInputList(list, EvalInputGroup::Surface, inputs, seenSurface);
    if (!error.empty()) return error;
  }
  return finishEvalInputs(inputs);
}

Json resultJson(const EvalResult& result, const EvalInputs& inputs, const IrGraph& graph, const std::string& hash) {
  Json outputs = Json::object(), coverage = Json::object();
  for (const auto& info : pbrFields()) outputs[std::string(info.name)] = valueJson(result.output(info.field));
  for (const auto& info : coverageTerms()) coverage[std::string(info.name)] = number(result.coverageOf(info.term));
  return {{"material", graph.name},
          {"contentHash", hash},
          {"weatherPreset", graph.weather.preset},
          {"inputs", inputsJson(inputs, graph)},
          {"outputs", std::move(outputs)},
          {"coverage", std::move(coverage)}};
}

// Runs the graph's ops at the point and prints the JSON.
int evaluateAndPrint(IrGraph ir, const EvalInputs& inputs, const Options& o) {
  TextureLoadResult textures = loadTextureSampler(ir.textures);
  if (!textures.sampler) {
    DiagnosticList list;
    list.report(DiagCode::TextureUnsupported, locateInJsonFile(o.graph, textures.pointer),
                {quoteUserText(textures.texture), quoteUserText(textures.reason)});
    printDiagnostics(list.items(), o.json);
    return kExitBadInput;
  }
  const std::string hash = contentHash(ir);
  const CpuEvaluator evaluator(std::move(ir), std::move(*textures.sampler));
  const EvalResult result = evaluator.evaluate(inputs);
  std::string text;
  writeJson(text, resultJson(result, inputs, evaluator.ir(), hash), 0);
  std::printf("%s\n", text.c_str());
  return kExitOk;
}

}  // namespace

int runEvalCommand(int argc, char** argv) {
  Options o;
  if (auto stop = parseEvalOptions(argc, argv, o)) return *stop;
  if (o.help && o.graph.empty()) {
    printHelp(nullptr);
    return kExitOk;
  }
  std::optional<IrGraph> ir = buildEvalGraph(o);
  if (!ir) return kExitBadInput;
  if (o.help) {
    printHelp(&*ir);
    return kExitOk;
  }
  EvalInputs inputs = defaultEvalInputs();
  if (std::string error = applyInputLists(o, *ir, inputs); !error.empty()) return usageError(error, o.json);
  return evaluateAndPrint(std::move(*ir), inputs, o);
}

}  // namespace wg
