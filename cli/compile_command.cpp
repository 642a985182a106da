// weathergen compile: graphs -> GLSL, HLSL, SPIR-V (+ .spvasm) and reflection JSON.
// Every graph is compiled before anything is written; on any error nothing is written.
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <thread>
#include <vector>

#include "cli/atomic_file.hpp"
#include "compiler/batch_compile.hpp"
#include "cli/depfile.hpp"
#include "cli/progress_line.hpp"
#include "cli/command_line.hpp"
#include "cli/commands.hpp"
#include "cli/diagnostic_output.hpp"
#include "compiler/literal.hpp"
#include "compiler/material_compiler.hpp"
#include "compiler/weather_config.hpp"

namespace wg {

namespace {

constexpr const char* kCompileUsage = R"(Usage: weathergen compile GRAPH... -o DIR [options]

Writes, for each material NAME:
  NAME.vert.glsl NAME.frag.glsl NAME.vert.hlsl NAME.frag.hlsl      (--target glsl, hlsl)
  NAME.{glsl,hlsl}.{vert,frag}.spv and .spvasm                     (--target spirv)
  NAME.vert.msl NAME.frag.msl                                      (--target msl)
  NAME.vert.es.glsl NAME.frag.es.glsl                              (--target glsles)
  NAME.reflect.json                                                (always)
  NAME.hpp                                                         (--emit-header)

Options:
  -o DIR, --output DIR       output directory (created if missing)
  --target LIST              comma-separated glsl, hlsl, spirv, msl, glsles, or all
                             (default: all = glsl,hlsl,spirv). MSL 2.0 and GLSL ES 3.10
                             are translated by SPIRV-Cross from the validated SPIR-V
                             of the GLSL stages
  -O                         optimise SPIR-V with spirv-opt's performance passes
  -O0                        no SPIR-V optimisation (default)
  -j N                       compile N graphs at once (default: one per core); the
                             output is byte-identical whatever N is
  --emit-header              write NAME.hpp: the material and frame uniform blocks as
                             C++ structs laid out as std140, with a static_assert on
                             every offset (docs/engine-api.md)
  --depfile FILE             write a Make-syntax depfile: each material's outputs
                             depend on its graph and its image files
  --weather-preset NAME      weather preset for every graph, replacing the graph's own
                             (rock, terrain, foliage, river, road, none)
  --diagnostics text|json    diagnostic format on stderr (default: text)
  -q, --quiet                print nothing but diagnostics
  -h, --help                 this help

Outputs are written atomically and only when every graph compiles.
)";

struct Targets {
  bool glsl = false, hlsl = false, spirv = false, msl = false, glslEs = false;
};

bool parseTargets(const std::string& list, Targets& t, std::string& error) {
  std::size_t start = 0;
  while (start <= list.size()) {
    std::size_t comma = list.find(',', start);
    std::string item = list.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    if (item == "glsl") t.glsl = true;
    else if (item == "hlsl") t.hlsl = true;
    else if (item == "spirv") t.spirv = true;
    else if (item == "msl") t.msl = true;
    else if (item == "glsles") t.glslEs = true;
    else if (item == "all") t.glsl = t.hlsl = t.spirv = true;
    else {
      error = "unknown target '" + quoteUserText(item) + "' (use glsl, hlsl, spirv, msl, glsles or all)";
      return false;
    }
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return true;
}

struct Options {
  std::vector<std::string> graphs;
  std::string outputDir;
  Targets targets;
  bool optimize = false;
  bool json = false;
  bool quiet = false;
  std::optional<std::string> weatherPreset;
  int jobs = 0;  // 0: one per core
  std::string depfile;
  bool emitHeader = false;
};


// Returns the files a material writes, path -> bytes.
std::map<std::string, std::string> outputsOf(const CompiledMaterial& m, const Options& o) {
  std::map<std::string, std::string> files;
  std::filesystem::path dir(o.outputDir);
  for (const auto& s : m.stages) {
    bool wantSource = s.language == ShaderLanguage::Glsl ? o.targets.glsl : o.targets.hlsl;
    if (wantSource) files[(dir / (m.fileStem + "." + stageFileSuffix(s.language, s.stage))).string()] = s.source;
    if (o.targets.spirv) {
      std::string base = m.fileStem + "." + std::string(languageName(s.language)) +
                         (s.stage == ShaderStage::Vertex ? ".vert" : ".frag");
      files[(dir / (base + ".spv")).string()] =
          std::string(reinterpret_cast<const char*>(s.spirv.data()), s.spirv.size() * sizeof(std::uint32_t));
      files[(dir / (base + ".spvasm")).string()] = s.disassembly;
    }
    // One translation per stage: the GLSL stages' SPIR-V (the HLSL stages' is equivalent).
    const char* stageName = s.stage == ShaderStage::Vertex ? ".vert" : ".frag";
    if (s.language == ShaderLanguage::Glsl && o.targets.msl)
      files[(dir / (m.fileStem + stageName + ".msl")).string()] = s.msl;
    if (s.language == ShaderLanguage::Glsl && o.targets.glslEs)
      files[(dir / (m.fileStem + stageName + ".es.glsl")).string()] = s.glslEs;
  }
  files[(dir / (m.fileStem + ".reflect.json")).string()] = m.reflectionJson;
  if (o.emitHeader) files[(dir / (m.fileStem + ".hpp")).string()] = m.cppHeader;
  return files;
}

}  // namespace

int runCompileCommand(int argc, char** argv) {
  CommandLine cl(argc, argv, 2);
  Options o;
  std::string targetList = "all";
  bool anyTarget = false;
  // Scan once for the diagnostics format so usage errors use it too.
  for (int i = 2; i < argc; ++i)
    if (std::string(argv[i]) == "--diagnostics=json" || (std::string(argv[i]) == "--diagnostics" && i + 1 < argc &&
                                                         std::string(argv[i + 1]) == "json"))
      o.json = true;
  while (!cl.done()) {
    std::string error;
    const std::string& arg = cl.peek();
    if (cl.endOfOptions() || arg.empty() || arg[0] != '-' || arg == "-") {
      o.graphs.push_back(cl.next());
      continue;
    }
    if (cl.flag("--")) {
      cl.markEndOfOptions();
      continue;
    }
    if (cl.flag("-h") || cl.flag("--help")) {
      std::fputs(kCompileUsage, stdout);
      return kExitOk;
    }
    if (cl.flag("-O")) {
      o.optimize = true;
      continue;
    }
    if (cl.flag("-O0")) {
      o.optimize = false;
      continue;
    }
    if (cl.flag("--emit-header")) {
      o.emitHeader = true;
      continue;
    }
    if (cl.flag("-q") || cl.flag("--quiet")) {
      o.quiet = true;
      continue;
    }
    if (auto v = cl.valueFor("--output", error); v || !error.empty()) {
      if (!v) return usageError(error, o.json);
      o.outputDir = *v;
      continue;
    }
    if (auto v = cl.valueFor("-o", error); v || !error.empty()) {
      if (!v) return usageError(error, o.json);
      o.outputDir = *v;
      continue;
    }
    if (auto v = cl.valueFor("--target", error); v || !error.empty()) {
      if (!v) return usageError(error, o.json);
      targetList = anyTarget ? targetList + "," + *v : *v;
      anyTarget = true;
      continue;
    }
    if (auto v = cl.valueFor("--weather-preset", error); v || !error.empty()) {
      if (!v) return usageError(error, o.json);
      if (std::string e = checkWeatherPresetName(*v); !e.empty()) return usageError(e, o.json);
      o.weatherPreset = *v;
      continue;
    }
    if (auto v = cl.valueFor("-j", error); v || !error.empty()) {
      if (!v) return usageError(error, o.json);
      char* end = nullptr;
      long jobs = std::strtol(v->c_str(), &end, 10);
      constexpr long kMaxJobs = 256;
      if (*end || jobs < 1 || jobs > kMaxJobs) return usageError("-j takes a job count from 1 to 256", o.json);
      o.jobs = static_cast<int>(jobs);
      continue;
    }
    if (auto v = cl.valueFor("--depfile", error); v || !error.empty()) {
      if (!v) return usageError(error, o.json);
      o.depfile = *v;
      continue;
    }
    if (auto v = cl.valueFor("--diagnostics", error); v || !error.empty()) {
      if (!v) return usageError(error, o.json);
      if (*v != "text" && *v != "json") return usageError("--diagnostics takes text or json", o.json);
      o.json = *v == "json";
      continue;
    }
    return usageError("unknown option '" + quoteUserText(arg) + "'", o.json);
  }
  std::string error;
  if (!parseTargets(targetList, o.targets, error)) return usageError(error, o.json);
  if (o.graphs.empty()) return usageError("no input graphs", o.json);
  if (o.outputDir.empty()) return usageError("no output directory; pass -o DIR", o.json);

  CompileOptions options;
  options.emitSpirv = o.targets.spirv;
  options.emitMsl = o.targets.msl;
  options.emitGlslEs = o.targets.glslEs;
  options.emitCppHeader = o.emitHeader;
  options.optimize = o.optimize;
  options.weatherPreset = o.weatherPreset;
  std::vector<Diagnostic> diagnostics;
  std::vector<CompiledMaterial> materials;
  std::map<std::string, std::string> stemOwner;
  bool internal = false;
  int jobs = o.jobs > 0 ? o.jobs : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  // Progress only for people: on a terminal, and not with -q or JSON diagnostics.
  ProgressLine progress(o.graphs.size(), !o.quiet && !o.json && ::isatty(STDERR_FILENO));
  std::vector<CompileResult> results = compileBatch(o.graphs, options, jobs, [&](std::size_t index, std::size_t done) {
    progress.update(done, o.graphs[index]);
  });
  progress.finish();
  for (std::size_t g = 0; g < o.graphs.size(); ++g) {
    const std::string& graph = o.graphs[g];
    CompileResult& r = results[g];
    for (auto& d : r.diagnostics.items()) {
      internal = internal || d.info().category == DiagCategory::Internal;
      diagnostics.push_back(std::move(d));
    }
    if (!r.material) continue;
    auto [it, inserted] = stemOwner.emplace(r.material->fileStem, graph);
    if (!inserted) {
      DiagnosticList list;
      list.report(DiagCode::InvalidSetting, {graph, "/name", 0, 0},
                  {"material '" + quoteUserText(r.material->name) + "' writes the same files as " + quoteUserText(it->second),
                   "give each material in one batch a distinct name"});
      diagnostics.push_back(list.items().front());
      continue;
    }
    materials.push_back(std::move(*r.material));
  }
  bool failed = false;
  for (const auto& d : diagnostics) failed = failed || d.info().severity == Severity::Error;
  if (!diagnostics.empty()) printDiagnostics(diagnostics, o.json);
  if (failed) return internal ? kExitInternal : kExitBadInput;

  std::error_code ec;
  std::filesystem::create_directories(o.outputDir, ec);
  if (ec) return usageError("cannot create output directory '" + quoteUserText(o.outputDir) + "'", o.json);
  std::size_t written = 0;
  std::vector<DepfileRule> rules;
  for (std::size_t k = 0; k < materials.size(); ++k) {
    const CompiledMaterial& m = materials[k];
    DepfileRule rule;
    for (const auto& [path, bytes] : outputsOf(m, o)) {
      if (std::string werror = writeFileAtomically(path, bytes); !werror.empty())
        return usageError(werror, o.json);
      rule.outputs.push_back(path);
      ++written;
    }
    rule.inputs.push_back(stemOwner.at(m.fileStem));
    for (const auto& t : m.ir.textures)
      if (!t.file.empty()) rule.inputs.push_back(t.resolvedPath);
    rules.push_back(std::move(rule));
  }
  if (!o.depfile.empty())
    if (std::string werror = writeFileAtomically(o.depfile, formatDepfile(rules)); !werror.empty())
      return usageError(werror, o.json);
  if (!o.quiet && !o.json && ::isatty(STDOUT_FILENO))
    std::printf("compiled %zu material%s, wrote %zu files to %s\n", materials.size(), materials.size() == 1 ? "" : "s",
                written, o.outputDir.c_str());
  return kExitOk;
}

}  // namespace wg
