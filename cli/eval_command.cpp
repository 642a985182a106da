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

#include "cli/command_line.hpp"
#include "cli/commands.hpp"
#include "cli/diagnostic_output.hpp"
#include "cli/eval_inputs.hpp"
#include "compiler/content_hash.hpp"
#include "compiler/graph_loader.hpp"
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
  --weather-preset NAME      weather preset, replacing the graph's own
                             (rock, terrain, foliage, river, road, none)
  --weather name=value,...   frame block weather members (below)
  --at name=value,...        surface inputs at the point (below)
  --param name=value,...     material parameters (with GRAPH, --help lists them)
  --diagnostics text|json    diagnostic format on stderr (default: text)
  -h, --help                 this help; with GRAPH, also the material's parameters

Vectors are written with ':' between components: normal=0:1:0, windDirection=1:0
(world x:z). Each option may be repeated; each key may be given once.
)";

// Column where --help starts an input's description.
constexpr int kHelpNameWidth = 32;
constexpr int kJsonIndent = 2;

struct Options {
  std::string graph;
  std::optional<std::string> weatherPreset;
  std::vector<std::pair<std::string, std::string>> lists;  // flag, "name=value,..." in order
  bool help = false;
  bool json = false;
};


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
  std::fputs(kEvalUsage, stdout);
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
std::optional<int> parseOptions(int argc, char** argv, Options& o) {
  CommandLine cl(argc, argv, 2);
  for (int i = 2; i < argc; ++i)
    if (std::string(argv[i]) == "--diagnostics=json" ||
        (std::string(argv[i]) == "--diagnostics" && i + 1 < argc && std::string(argv[i + 1]) == "json"))
      o.json = true;
  std::vector<std::string> graphs;
  while (!cl.done()) {
    std::string error;
    const std::string& arg = cl.peek();
    if (cl.endOfOptions() || arg.empty() || arg[0] != '-' || arg == "-") {
      graphs.push_back(cl.next());
      continue;
    }
    if (cl.flag("--")) {
      cl.markEndOfOptions();
      continue;
    }
    if (cl.flag("-h") || cl.flag("--help")) {
      o.help = true;
      continue;
    }
    bool matched = false;
    for (const char* flag : {"--weather", "--at", "--param"}) {
      if (auto v = cl.valueFor(flag, error); v || !error.empty()) {
        if (!v) return usageError(error, o.json);
        o.lists.emplace_back(flag, *v);
        matched = true;
        break;
      }
    }
    if (matched) continue;
    if (auto v = cl.valueFor("--weather-preset", error); v || !error.empty()) {
      if (!v) return usageError(error, o.json);
      if (std::string e = checkWeatherPresetName(*v); !e.empty()) return usageError(e, o.json);
      o.weatherPreset = *v;
      continue;
    }
    if (auto v = cl.valueFor("--diagnostics", error); v || !error.empty()) {
      if (!v) return usageError(error, o.json);
      if (*v != "text" && *v != "json") return usageError("--diagnostics takes text or json", o.json);
      o.json = *v == "json";
      continue;
    }
    return usageError("unknown option '" + quoteUserText(arg) + "'; run 'weathergen eval --help' for the options", o.json);
  }
  if (graphs.size() > 1) return usageError("eval takes one graph, got " + std::to_string(graphs.size()), o.json);
  if (graphs.empty() && !o.help) return usageError("no input graph; write 'weathergen eval GRAPH'", o.json);
  if (!graphs.empty()) o.graph = graphs.front();
  return std::nullopt;
}

// Objects one member a line and arrays on one line ("baseColor": [0.5, 0.4, 0.3]), so
// vectors read as vectors.
void writeJson(std::string& out, const Json& value, int depth) {
  auto dump = [](const Json& j) { return j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace); };
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

}  // namespace

int runEvalCommand(int argc, char** argv) {
  Options o;
  if (auto stop = parseOptions(argc, argv, o)) return *stop;
  if (o.help && o.graph.empty()) {
    printHelp(nullptr);
    return kExitOk;
  }

  DiagnosticList diagnostics;
  std::optional<IrGraph> ir;
  if (auto text = readGraphFile(o.graph, diagnostics))
    ir = buildOptimizedIr(o.graph, std::move(*text), diagnostics, CompileOptions{.weatherPreset = o.weatherPreset});
  if (!diagnostics.empty()) printDiagnostics(diagnostics.items(), o.json);
  if (!ir || diagnostics.hasErrors()) return kExitBadInput;
  if (o.help) {
    printHelp(&*ir);
    return kExitOk;
  }

  EvalInputs inputs = defaultEvalInputs();
  std::set<std::string> seenWeather, seenSurface, seenParameters;
  for (const auto& [flag, list] : o.lists) {
    std::string error = flag == "--param"     ? applyParameterList(list, *ir, inputs, seenParameters)
                        : flag == "--weather" ? applyEvalInputList(list, EvalInputGroup::Weather, inputs, seenWeather)
                                              : applyEvalInputList(list, EvalInputGroup::Surface, inputs, seenSurface);
    if (!error.empty()) return usageError(error, o.json);
  }
  if (std::string error = finishEvalInputs(inputs); !error.empty()) return usageError(error, o.json);

  TextureLoadResult textures = loadTextureSampler(ir->textures);
  if (!textures.sampler) {
    DiagnosticList list;
    list.report(DiagCode::TextureUnsupported, locateInJsonFile(o.graph, textures.pointer),
                {quoteUserText(textures.texture), quoteUserText(textures.reason)});
    printDiagnostics(list.items(), o.json);
    return kExitBadInput;
  }
  const std::string hash = contentHash(*ir);
  const CpuEvaluator evaluator(std::move(*ir), std::move(*textures.sampler));
  const EvalResult result = evaluator.evaluate(inputs);
  const IrGraph& graph = evaluator.ir();

  Json outputs = Json::object(), coverage = Json::object();
  for (const auto& info : pbrFields()) outputs[std::string(info.name)] = valueJson(result.output(info.field));
  for (const auto& info : coverageTerms()) coverage[std::string(info.name)] = number(result.coverageOf(info.term));
  Json root = {{"material", graph.name},
               {"contentHash", hash},
               {"weatherPreset", graph.weather.preset},
               {"inputs", inputsJson(inputs, graph)},
               {"outputs", std::move(outputs)},
               {"coverage", std::move(coverage)}};
  std::string text;
  writeJson(text, root, 0);
  std::printf("%s\n", text.c_str());
  return kExitOk;
}

}  // namespace wg
