// weathergen compile: graphs -> GLSL, HLSL, SPIR-V (+ .spvasm) and reflection JSON.
// Every graph is compiled before anything is written; on any error nothing is written.
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <thread>
#include <tuple>
#include <vector>

#include "cli/atomic_file.hpp"
#include "cli/number_text.hpp"
#include "cli/material_outputs.hpp"
#include "cli/variant_plan.hpp"
#include "compiler/variant_index.hpp"
#include "driver/batch_compile.hpp"
#include "driver/compile_cache.hpp"
#include "cli/depfile.hpp"
#include "cli/effect_overrides_option.hpp"
#include "cli/flag_file.hpp"
#include "cli/persistent_worker.hpp"
#include "cli/run_inputs.hpp"
#include "cli/staged_directory.hpp"
#include "cli/progress_line.hpp"
#include "cli/option_table.hpp"
#include "cli/commands.hpp"
#include "cli/diagnostic_output.hpp"
#include "cli/ir_dump.hpp"
#include "compiler/literal.hpp"
#include "driver/material_compiler.hpp"
#include "compiler/weather_config.hpp"

namespace wg {

namespace {

constexpr const char* kPersistentWorkerFlag = "--persistent_worker";  // Bazel's spelling

constexpr const char* kCompileUsageHead = R"(Usage: weathergen compile GRAPH... -o DIR [options]

Writes, for each material NAME:
)";
constexpr const char* kCompileUsageTail = R"(  NAME.reflect.json                                                (always)
  NAME.hpp                                                         (--emit-header)
With --variants, each file set is named NAME.HASH.* after its content hash, so variants
with identical shaders share one set, and NAME.variants.json maps each variant to it.

Options:
)";
constexpr const char* kCompileUsageEnd = R"(
Outputs are written atomically and only when every graph compiles.
)";

// The targets' lines of the usage text, from the target table.
std::string targetUsage() {
  std::string text;
  for (const auto& target : outputTargets()) {
    std::string line = "  " + std::string(target.files);
    line.resize(std::max<std::size_t>(line.size() + 1, 67), ' ');
    text += line + "(--target " + std::string(target.name) + (target.inAll ? ", all" : "") + ")\n";
  }
  return text;
}

struct Options {
  std::vector<std::string> graphs;
  std::string outputDir;
  std::optional<std::string> targetList;  // every --target, joined by commas
  OutputTargets targets;
  bool optimize = false;
  bool json = false;
  bool quiet = false;
  bool help = false;
  std::optional<std::string> weatherPreset;
  std::optional<std::string> quality;
  WeatherEffectOverrides effects;
  int jobs = 0;  // 0: one per core
  std::string depfile;
  std::optional<std::string> cacheDir;  // --cache; else $WEATHERGEN_CACHE_DIR, else the user's cache
  bool noCache = false;
  std::optional<VariantSelection> variants;
  std::optional<std::string> dumpIrAfter;  // a pass name or "all": print IR, write nothing
};

std::string setJobs(const std::string& v, int& jobs) {
  constexpr std::uint32_t kMaxJobs = 256;
  const auto count = parseCountText(v, 1, kMaxJobs);
  if (!count) return "-j takes a job count from 1 to 256";
  jobs = static_cast<int>(*count);
  return "";
}

std::string setDepfile(const std::string& v, std::string& depfile) {
  if (v.empty()) return "--depfile takes a file name (it is empty; is a build variable unset?)";
  depfile = v;
  return "";
}

std::string setVariants(const std::string& v, std::optional<VariantSelection>& variants) {
  std::string error;
  variants = parseVariantSelection(v, error);
  return error;
}

std::string setCacheDirectory(const std::string& v, std::optional<std::string>& dir) {
  if (v.empty()) return "--cache takes a directory (it is empty; is a build variable unset?)";
  dir = v;
  return "";
}

// What is written, and where.
std::vector<Option> outputOptions(Options& o) {
  auto addTargets = [&o](const std::string& v) {
    o.targetList = o.targetList ? *o.targetList + "," + v : v;
    return std::string();
  };
  return {
      {"--output", "-o", "DIR", "output directory (created if missing)", storeValue(o.outputDir)},
      {"--target", "", "LIST",
       "comma-separated glsl, hlsl, spirv, msl, glsles, or all\n"
       "(default: all = glsl,hlsl,spirv). MSL 2.0 and GLSL ES 3.10\n"
       "are translated by SPIRV-Cross from the validated SPIR-V\n"
       "of the GLSL stages",
       addTargets},
      {"-O", "", "", "optimise SPIR-V with spirv-opt's performance passes", storeFlag(o.optimize)},
      {"-O0", "", "", "no SPIR-V optimisation (default)", storeFlag(o.optimize, false)},
      {"-j", "", "N", "compile N graphs at once (default: one per core); the\noutput is byte-identical whatever N is",
       [&o](const std::string& v) { return setJobs(v, o.jobs); }},
      {"--emit-header", "", "",
       "write NAME.hpp: the material and frame uniform blocks as\n"
       "C++ structs laid out as std140, with a static_assert on\n"
       "every offset (docs/engine-api.md)",
       storeFlag(o.targets.header)},
      {"--depfile", "", "FILE",
       "write a Make-syntax depfile: each material's outputs\n"
       "depend on its graph, its graph libraries and its\n"
       "image files",
       [&o](const std::string& v) { return setDepfile(v, o.depfile); }},
      {"--cache", "", "DIR",
       "reuse and keep compiled materials in DIR, keyed by the\n"
       "content of every file read and the options (default:\n"
       "$WEATHERGEN_CACHE_DIR when set, 'off' for none, else\n"
       "$XDG_CACHE_HOME/weathergen or ~/.cache/weathergen)",
       [&o](const std::string& v) { return setCacheDirectory(v, o.cacheDir); }},
      {"--no-cache", "", "", "compile every graph; use and keep no cache", storeFlag(o.noCache)},
  };
}

// Which materials, how they are reported, and debugging.
std::vector<Option> materialAndReportOptions(Options& o) {
  return {
      {"--variants", "", "all|LIST",
       "compile static-switch variants (docs/graph-format.md): all\n"
       "permutations, or LIST = SWITCH[=VALUE|VALUE...],... where a\n"
       "bare SWITCH means all its values; others keep their default",
       [&o](const std::string& v) { return setVariants(v, o.variants); }},
      {"--weather-preset", "", "NAME",
       "weather preset for every graph, replacing the graph's own\n(rock, terrain, foliage, river, road, none)",
       storeChecked(o.weatherPreset, checkWeatherPresetName)},
      {"--quality", "", "TIER", kQualityOptionHelp, storeChecked(o.quality, checkQualityTierName)},
      {"--effects", "", "LIST", kEffectsOptionHelp,
       [&o](const std::string& v) { return addEffectOverrides(v, o.effects); }},
      {"--diagnostics", "", "text|json", "diagnostic format on stderr (default: text)",
       [&o](const std::string& v) { return setDiagnosticsFormat(v, o.json); }},
      {"--quiet", "-q", "", "print nothing but diagnostics", storeFlag(o.quiet)},
      {"--dump-ir-after", "", "PASS",
       "debugging: print the IR after PASS (see list-passes; 'all'\n"
       "prints it after every pass) on stdout and write nothing;\n"
       "-o is not needed",
       storeChecked(o.dumpIrAfter, checkDumpIrPassName)},
      {"--flagfile", "", "FILE",
       "read more arguments from FILE, one a line (Bazel's\n"
       "multiline parameter files; LF or CRLF line ends, an\n"
       "empty line is an empty argument)",
       [](const std::string&) { return std::string("--flagfile is not read inside a flag file"); }},
      {kPersistentWorkerFlag, "", "",
       "serve Bazel's persistent worker protocol (JSON) on stdin\n"
       "and stdout: each request's arguments, after the others on\n"
       "this command line, are one compile's",
       [](const std::string&) {
         return std::string(kPersistentWorkerFlag) + " belongs on the worker's own command line, not in a request or a flag file";
       }},
      {"--help", "-h", "", "this help", storeFlag(o.help), true},
  };
}

OptionTable compileOptionTable(Options& o) {
  OptionTable table{.operand = [&o](const std::string& graph) {
    if (graph.empty())
      return std::string(
          "an empty argument where a graph file was expected (an empty line in a flag file, or an unset build variable?)");
    o.graphs.push_back(graph);
    return std::string();
  }};
  table.options = outputOptions(o);
  for (auto& option : materialAndReportOptions(o)) table.options.push_back(std::move(option));
  return table;
}

// Reads the arguments after "compile" into `o`; an exit code when the command is done
// (--help, or a usage error already printed).
std::optional<int> parseCompileOptions(const std::vector<std::string>& arguments, Options& o) {
  o.json = jsonDiagnosticsRequested(arguments);
  std::string error;
  const std::optional<std::vector<std::string>> args = expandFlagFiles(arguments, error);
  if (!args) return usageError(error, o.json);
  o.json = o.json || jsonDiagnosticsRequested(*args);
  const OptionTable table = compileOptionTable(o);
  CommandLine commandLine(*args);
  const OptionParseResult parsed = parseOptions(table, commandLine);
  if (parsed.status == OptionParse::Failed) return usageError(parsed.error, o.json);
  if (o.help) {
    std::fputs((kCompileUsageHead + targetUsage() + kCompileUsageTail + formatOptionList(table) + kCompileUsageEnd).c_str(),
               stdout);
    return kExitOk;
  }
  auto targets = parseOutputTargets(o.targetList.value_or("all"), error);
  if (!targets) return usageError(error, o.json);
  targets->header = o.targets.header;  // set by --emit-header
  o.targets = *targets;
  if (o.graphs.empty()) return usageError("no input graphs", o.json);
  if (o.outputDir.empty() && !o.dumpIrAfter) return usageError("no output directory; pass -o DIR", o.json);
  return std::nullopt;
}

// One graph's compiled variants: their files (shared by identical variants) and, with
// --variants, the index NAME.variants.json.
struct GraphOutput {
  std::string graph;
  std::string stem;  // NAME, safe for file names
  std::vector<const CompiledMaterial*> variants;
  std::vector<SwitchValues> switches;
};

// path -> bytes, views into the compiled materials (and the variant indexes).
using OutputFiles = std::map<std::string, std::string_view>;

// One graph's files. Identical variants have one content hash and so one file set; the
// bytes are compared anyway, so a hash collision could never lose a shader. With
// --variants, the index is kept in `indexes` (a deque: its texts never move).
std::optional<OutputFiles> graphFiles(const GraphOutput& g, const std::vector<SwitchDecl>& declared, const Options& o,
                                      std::deque<std::string>& indexes, std::string& error) {
  OutputFiles files;
  std::vector<VariantEntry> entries;
  for (std::size_t v = 0; v < g.variants.size(); ++v) {
    const CompiledMaterial& m = *g.variants[v];
    for (auto& [path, bytes] : materialOutputs(m, o.targets, o.outputDir)) {
      auto [it, inserted] = files.emplace(path, bytes);
      if (!inserted && it->second != bytes) {
        error = "two variants of " + quoteUserText(g.graph) + " differ but share the content hash " + m.contentHash;
        return std::nullopt;
      }
    }
    entries.push_back({g.switches[v], m.contentHash, m.fileStem});
  }
  if (o.variants)
    files[(std::filesystem::path(o.outputDir) / (g.stem + ".variants.json")).string()] =
        indexes.emplace_back(buildVariantIndexJson(g.variants.front()->name, declared, entries));
  return files;
}

// No output, the depfile included, may replace an input (a graph, a library or an
// image: RunInputs), nor may the depfile replace an output.
std::string outputOverwritesInput(const std::vector<DepfileRule>& rules, const std::string& depfile) {
  RunInputs inputs;
  std::vector<PlannedOutput> outputs;
  for (const auto& rule : rules) {
    inputs.add(rule.inputs);
    for (const auto& output : rule.outputs) outputs.push_back({"-o", output});
  }
  if (!depfile.empty()) outputs.push_back({"--depfile", depfile});
  if (std::string e = inputs.checkOutputs(outputs); !e.empty()) return e;
  if (depfile.empty()) return "";
  if (std::string e = checkNoSpecialFiles({{"--depfile", depfile}}); !e.empty()) return e;
  // What follows asks only whether the depfile is an output.
  std::error_code ec;
  std::set<std::filesystem::path> written;
  for (const auto& rule : rules)
    for (const auto& output : rule.outputs) written.insert(std::filesystem::weakly_canonical(output, ec));
  if (written.count(std::filesystem::weakly_canonical(depfile, ec)))
    return "--depfile '" + quoteUserText(depfile) + "' is one of the outputs; choose another path";
  return "";
}

// The depfile is written last, so its folder is checked before any output is published.
std::string checkDepfileTarget(const std::string& depfile) {
  if (depfile.empty()) return "";
  std::error_code ec;
  if (std::filesystem::is_directory(depfile, ec)) return "--depfile '" + quoteUserText(depfile) + "' is a directory; name a file";
  std::filesystem::path folder = std::filesystem::absolute(depfile, ec).parent_path();
  if (!std::filesystem::is_directory(folder, ec))
    return "--depfile '" + quoteUserText(depfile) + "': its folder does not exist; create it first";
  return "";
}

CompileOptions compileOptionsFor(const Options& o) {
  CompileOptions options;
  applyOutputTargets(o.targets, options);
  options.optimize = o.optimize;
  options.weatherPreset = o.weatherPreset;
  options.weatherEffects = o.effects;
  options.quality.requested = o.quality;
  options.hashKeyedFileStem = o.variants.has_value();
  return options;
}

// The user's cache directory (XDG's base directories), or none without an absolute
// $XDG_CACHE_HOME or $HOME.
std::optional<std::string> userCacheDirectory() {
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && xdg[0] == '/') return std::string(xdg) + "/weathergen";
  if (const char* home = std::getenv("HOME"); home && home[0] == '/') return std::string(home) + "/.cache/weathergen";
  return std::nullopt;
}

// --cache DIR, else $WEATHERGEN_CACHE_DIR ("off": none), else the user's cache
// directory; none with --no-cache. A directory the user named must work; the default
// one is a convenience, and without it the compile runs uncached.
std::string openCompileCache(const Options& o, std::optional<CompileCache>& cache) {
  if (o.noCache || o.dumpIrAfter) return "";
  const char* fromEnvironment = std::getenv("WEATHERGEN_CACHE_DIR");
  const bool environmentNames = fromEnvironment && *fromEnvironment;
  if (!o.cacheDir && environmentNames && std::string_view(fromEnvironment) == "off") return "";
  std::optional<std::string> directory =
      o.cacheDir ? o.cacheDir : environmentNames ? std::optional<std::string>(fromEnvironment) : userCacheDirectory();
  if (!directory) return "";
  cache.emplace(*directory);
  std::string problem = cache->prepare();
  if (problem.empty()) return "";
  cache.reset();
  if (!o.cacheDir && !environmentNames) return "";
  return (o.cacheDir ? "--cache " : "WEATHERGEN_CACHE_DIR: ") + problem;
}

std::vector<CompileResult> compileJobs(const VariantPlan& plan, const CompileOptions& options, const Options& o) {
  int jobs = o.jobs > 0 ? o.jobs : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  // Progress only for people: on a terminal, and not with -q or JSON diagnostics.
  ProgressLine progress(plan.jobs.size(), !o.quiet && !o.json && ::isatty(STDERR_FILENO));
  std::vector<CompileResult> results = compileBatch(plan.jobs, options, jobs, [&](std::size_t index, std::size_t done) {
    const CompileJob& job = plan.jobs[index];
    const SwitchValues& variant = plan.variantOf[index];
    progress.update(done, variant.empty() ? job.graph : job.graph + " [" + variantName(variant) + "]");
  });
  progress.finish();
  return results;
}

// What the batch reported, each diagnostic once, and whether any was internal.
struct BatchDiagnostics {
  std::vector<Diagnostic> items;
  bool internal = false;

  // The same diagnostic from several variants of one graph is kept once; a set, so that
  // a batch of many failing graphs costs n log n, not n squared.
  void addUnique(Diagnostic d) {
    if (!seen_.emplace(d.code, d.location.file, d.location.pointer, d.message).second) return;
    items.push_back(std::move(d));
  }

 private:
  std::set<std::tuple<DiagCode, std::string, std::string, std::string>> seen_;
};

// Each graph's compiled variants, in the order of the graphs.
std::vector<GraphOutput> groupByGraph(const VariantPlan& plan, std::vector<CompileResult>& results,
                                      std::size_t graphCount, BatchDiagnostics& diagnostics) {
  std::vector<GraphOutput> outputs(graphCount);
  for (std::size_t j = 0; j < plan.jobs.size(); ++j) {
    CompileResult& r = results[j];
    for (auto& d : r.diagnostics.items()) {
      diagnostics.internal = diagnostics.internal || d.info().category == DiagCategory::Internal;
      diagnostics.addUnique(std::move(d));
    }
    if (!r.material) continue;
    GraphOutput& g = outputs[plan.graphOf[j]];
    g.graph = plan.jobs[j].graph;
    g.stem = fileStemFor(r.material->name);
    g.variants.push_back(&*r.material);
    g.switches.push_back(plan.variantOf[j]);
  }
  return outputs;
}

// Two graphs whose materials would write the same file names (WG2020).
void reportNameCollisions(const std::vector<GraphOutput>& outputs, std::vector<Diagnostic>& diagnostics) {
  std::map<std::string, std::string> stemOwner;
  for (const auto& g : outputs) {
    if (g.variants.empty()) continue;
    auto [it, inserted] = stemOwner.emplace(g.stem, g.graph);
    if (inserted) continue;
    DiagnosticList list;
    list.report(DiagCode::OutputNameCollision, {g.graph, "/name", 0, 0},
                {quoteUserText(g.variants.front()->name), quoteUserText(it->second)});
    diagnostics.push_back(list.items().front());
  }
}

// Prints the diagnostics; the exit code when one of them is an error.
std::optional<int> reportDiagnostics(const BatchDiagnostics& diagnostics, bool json) {
  bool failed = false, badInput = false;
  for (const auto& d : diagnostics.items) {
    failed = failed || d.info().severity == Severity::Error;
    badInput = badInput || (d.info().severity == Severity::Error && d.info().category == DiagCategory::Input);
  }
  if (!diagnostics.items.empty()) printDiagnostics(diagnostics.items, json);
  // Only a batch's colliding names (WG2020, usage) leave every graph valid on its own.
  if (!failed) return std::nullopt;
  return diagnostics.internal ? kExitInternal : badInput ? kExitBadInput : kExitUsage;
}

// Every file of every graph, known before the first is written; an exit code when two
// variants disagree.
std::optional<int> collectFiles(const std::vector<GraphOutput>& outputs, const VariantPlan& plan, const Options& o,
                                std::vector<OutputFiles>& filesOf, std::deque<std::string>& indexes) {
  for (std::size_t g = 0; g < outputs.size(); ++g) {
    std::string error;
    auto files = graphFiles(outputs[g], plan.switchesOf[g], o, indexes, error);
    if (!files) {
      DiagnosticList list;
      list.report(DiagCode::InternalException, {outputs[g].graph, "", 0, 0}, {error});
      printDiagnostics(list.items(), o.json);
      return kExitInternal;
    }
    filesOf.push_back(std::move(*files));
  }
  return std::nullopt;
}

// Per graph: its files depend on the graph, its libraries and images, over every variant.
std::vector<DepfileRule> depfileRules(const std::vector<GraphOutput>& outputs,
                                      const std::vector<OutputFiles>& filesOf) {
  std::vector<DepfileRule> rules;
  for (std::size_t g = 0; g < outputs.size(); ++g) {
    DepfileRule rule;
    for (const auto& [path, bytes] : filesOf[g]) rule.outputs.push_back(path);
    rule.inputs.push_back(outputs[g].graph);
    std::set<std::string> readFiles;
    for (const CompiledMaterial* m : outputs[g].variants) readFiles.insert(m->inputFiles.begin(), m->inputFiles.end());
    rule.inputs.insert(rule.inputs.end(), readFiles.begin(), readFiles.end());
    rules.push_back(std::move(rule));
  }
  return rules;
}

// All or nothing: every output is staged, then published together, then the depfile.
// Returns the exit code and counts the files written.
int writeOutputs(const std::vector<OutputFiles>& filesOf, const std::vector<DepfileRule>& rules,
                 const Options& o, std::size_t& written) {
  // The depfile is formatted before anything is written: a path it cannot express
  // safely stops the run with nothing written.
  std::string depfileError;
  std::optional<std::string> depfileText;
  if (!o.depfile.empty() && !(depfileText = formatDepfile(rules, depfileError))) return usageError(depfileError, o.json);
  if (std::string e = outputOverwritesInput(rules, o.depfile); !e.empty()) return usageError(e, o.json);
  if (std::string e = checkDepfileTarget(o.depfile); !e.empty()) return usageError(e, o.json);
  StagedDirectory staged(o.outputDir);
  for (const auto& files : filesOf)
    for (const auto& [path, bytes] : files) {
      if (std::string e = staged.stage(std::filesystem::path(path).filename().string(), bytes); !e.empty()) return usageError(e, o.json);
      ++written;
    }
  if (std::string e = staged.publish(); !e.empty()) return usageError(e, o.json);
  if (depfileText)
    if (std::string werror = writeFileAtomically(o.depfile, *depfileText); !werror.empty()) return usageError(werror, o.json);
  return kExitOk;
}

// Writes every graph's files and prints the summary line on a terminal.
int writeCompiled(const std::vector<GraphOutput>& outputs, const VariantPlan& plan, const Options& o) {
  std::vector<OutputFiles> filesOf;
  std::deque<std::string> indexes;
  if (auto exit = collectFiles(outputs, plan, o, filesOf, indexes)) return *exit;
  std::size_t written = 0, compiled = 0;
  for (const auto& g : outputs) compiled += g.variants.size();
  if (int e = writeOutputs(filesOf, depfileRules(outputs, filesOf), o, written)) return e;
  if (!o.quiet && !o.json && ::isatty(STDOUT_FILENO))
    std::printf("compiled %zu material%s (%zu variant%s), wrote %zu files to %s\n", outputs.size(),
                outputs.size() == 1 ? "" : "s", compiled, compiled == 1 ? "" : "s", written, o.outputDir.c_str());
  return kExitOk;
}

// One compile: the arguments after "compile".
int compileWith(const std::vector<std::string>& arguments) {
  Options o;
  if (auto exit = parseCompileOptions(arguments, o)) return *exit;
  CompileOptions options = compileOptionsFor(o);
  VariantPlan plan;
  if (std::string e = planVariants(o.graphs, o.variants, options.quality, plan); !e.empty()) return usageError(e, o.json);
  std::optional<CompileCache> cache;
  if (std::string e = openCompileCache(o, cache); !e.empty()) return usageError(e, o.json);
  if (o.dumpIrAfter) return dumpIrAfterPass(plan.jobs, *o.dumpIrAfter, options, o.json);
  options.cache = cache ? &*cache : nullptr;
  std::vector<CompileResult> results = compileJobs(plan, options, o);
  if (cache) cache->trim();
  BatchDiagnostics diagnostics;
  std::vector<GraphOutput> outputs = groupByGraph(plan, results, o.graphs.size(), diagnostics);
  reportNameCollisions(outputs, diagnostics.items);
  if (auto exit = reportDiagnostics(diagnostics, o.json)) return *exit;
  return writeCompiled(outputs, plan, o);
}

}  // namespace

// With --persistent_worker (Bazel adds it to the worker's own command line) the other
// arguments come first in every request's compile.
int runCompileCommand(int argc, char** argv) {
  std::vector<std::string> arguments(argv + 2, argv + argc);
  const auto operands = std::find(arguments.begin(), arguments.end(), "--");
  const auto kept = std::remove(arguments.begin(), operands, kPersistentWorkerFlag);  // each, if given twice
  if (kept == operands) return compileWith(arguments);
  arguments.erase(kept, operands);
  return runPersistentWorker([&arguments](const std::vector<std::string>& request) {
    std::vector<std::string> all = arguments;
    all.insert(all.end(), request.begin(), request.end());
    return compileWith(all);
  });
}

}  // namespace wg
