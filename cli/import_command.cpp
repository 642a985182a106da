// weathergen import: glTF 2.0 materials -> weather-aware material graphs
// (docs/gltf-import.md).
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "cli/command_line.hpp"
#include "cli/commands.hpp"
#include "cli/diagnostic_output.hpp"
#include "cli/staged_directory.hpp"
#include "compiler/literal.hpp"
#include "import/gltf_asset.hpp"
#include "import/model_import.hpp"

namespace wg {

namespace {

constexpr const char* kImportUsage = R"(Usage: weathergen import MODEL.gltf|MODEL.glb -o DIR [options]

Writes one material graph per glTF material (MODEL_MATERIAL.json), the model's images
beside them (MODEL_imageN.png|jpg) and MODEL.import.json, the index from each glTF
material (index and name) to its graph. Nothing is written if the model has an error.

Options:
  -o DIR, --output DIR       where to write (created if missing)
  --weather-preset NAME      every material's weather: rock, terrain, foliage, river,
                             road or none (default: rock)
  --preset-map RULES         per material: 'GLOB=PRESET,...' matched against material
                             names in order, e.g. '*Ground*=terrain,*Leaf*=foliage,*=rock';
                             a material no rule matches gets no weather
  --snow-displacement        keep the presets' snow displacement (off by default: it moves
                             vertices along their normals, which tears meshes that are
                             split at hard edges, as most glTF meshes are)
  --diagnostics text|json    diagnostic format on stderr (default: text)
  -q, --quiet                no summary line (on stdout)
)";

struct ImportOptions {
  std::string model, outputDir, preset = "rock", presetMap;
  bool json = false, quiet = false, help = false, presetGiven = false, displacement = false;
};

// Returns -1 when parsing succeeded, else the exit code.
int parseOptions(int argc, char** argv, ImportOptions& o) {
  CommandLine cl(argc, argv, 2);
  while (!cl.done()) {
    std::string error;
    if (!cl.endOfOptions() && cl.peek() == "--") {
      cl.next();
      cl.markEndOfOptions();
      continue;
    }
    if (cl.endOfOptions() || cl.peek().empty() || cl.peek()[0] != '-') {
      if (!o.model.empty()) return usageError("import takes one model; got '" + quoteUserText(o.model) + "' and '" + quoteUserText(cl.peek()) + "'", o.json);
      o.model = cl.next();
      continue;
    }
    if (cl.flag("-h") || cl.flag("--help")) { o.help = true; continue; }
    if (cl.flag("-q") || cl.flag("--quiet")) { o.quiet = true; continue; }
    if (cl.flag("--snow-displacement")) { o.displacement = true; continue; }
    if (auto v = cl.valueFor("-o", error)) { o.outputDir = *v; continue; }
    if (auto v = cl.valueFor("--output", error)) { o.outputDir = *v; continue; }
    if (auto v = cl.valueFor("--diagnostics", error)) {
      if (*v != "text" && *v != "json") return usageError("--diagnostics takes text or json", o.json);
      o.json = *v == "json";
      continue;
    }
    if (auto v = cl.valueFor("--weather-preset", error)) {
      if (std::string e = checkWeatherPresetName(*v); !e.empty()) return usageError(e, o.json);
      o.preset = *v;
      o.presetGiven = true;
      continue;
    }
    if (auto v = cl.valueFor("--preset-map", error)) {
      if (v->empty()) return usageError("--preset-map takes rules, e.g. '*Leaf*=foliage,*=rock'", o.json);
      o.presetMap = *v;
      continue;
    }
    if (!error.empty()) return usageError(error, o.json);
    return usageError("unknown option '" + quoteUserText(cl.peek()) + "'; run 'weathergen import --help'", o.json);
  }
  if (o.help) return -1;
  if (o.model.empty()) return usageError("no model; write 'weathergen import MODEL.gltf -o DIR'", o.json);
  if (o.outputDir.empty()) return usageError("no output directory; pass -o DIR", o.json);
  if (o.presetGiven && !o.presetMap.empty()) return usageError("--weather-preset and --preset-map exclude each other", o.json);
  return -1;
}

// The model and the files it reads must never be replaced by an output.
std::string outputOverwritesInput(const gltf::Asset& asset, const std::filesystem::path& dir, const gltf::ImportedModel& imported) {
  std::error_code ec;
  std::vector<std::filesystem::path> inputs;
  for (const auto& f : asset.inputFiles()) inputs.push_back(std::filesystem::weakly_canonical(f, ec));
  for (const auto& f : imported.files) {
    std::filesystem::path target = std::filesystem::weakly_canonical(dir / f.name, ec);
    if (std::find(inputs.begin(), inputs.end(), target) != inputs.end())
      return "the output '" + quoteUserText(f.name) + "' would replace the model or a file it reads";
  }
  return "";
}

int writeImport(const gltf::Asset& asset, const gltf::ImportedModel& imported, const ImportOptions& o) {
  if (std::string e = outputOverwritesInput(asset, o.outputDir, imported); !e.empty())
    return usageError(e + "; choose another output directory", o.json);
  StagedDirectory out(o.outputDir);
  for (const auto& f : imported.files)
    if (std::string e = out.stage(f.name, f.bytes); !e.empty()) return usageError(e, o.json);
  if (std::string e = out.publish(); !e.empty()) return usageError(e, o.json);
  if (!o.quiet)
    std::printf("import: %zu material graph(s) and %zu image(s) from %s into %s (index: %s)\n",
                 imported.materialGraphs.size() + (imported.defaultGraph.empty() ? 0 : 1), asset.model.images.size(),
                 quoteUserText(asset.file, 200).c_str(), quoteUserText(o.outputDir, 200).c_str(), imported.indexFile.c_str());
  return kExitOk;
}

}  // namespace

int runImportCommand(int argc, char** argv) {
  ImportOptions o;
  if (int code = parseOptions(argc, argv, o); code >= 0) return code;
  if (o.help) {
    std::fputs(kImportUsage, stdout);
    return kExitOk;
  }
  std::string error;
  auto presets = o.presetMap.empty() ? std::optional(gltf::PresetChoice::everywhere(o.preset))
                                     : gltf::PresetChoice::fromMap(o.presetMap, error);
  if (!presets) return usageError(error, o.json);
  DiagnosticList diagnostics;
  auto asset = gltf::loadAsset(o.model, diagnostics);
  std::optional<gltf::ModelGeometry> geometry;
  if (asset) geometry = gltf::readModelGeometry(*asset, diagnostics);
  std::optional<gltf::ImportedModel> imported;
  if (geometry) imported = gltf::importModel(*asset, *geometry, {*presets, o.displacement}, diagnostics);
  printDiagnostics(diagnostics.items(), o.json);
  if (!imported) return kExitBadInput;
  return writeImport(*asset, *imported, o);
}

}  // namespace wg
