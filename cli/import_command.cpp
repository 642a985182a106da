// weathergen import: glTF 2.0 and MaterialX materials -> weather-aware material graphs
// (docs/gltf-import.md, docs/materialx-import.md).
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "cli/commands.hpp"
#include "cli/diagnostic_output.hpp"
#include "cli/option_table.hpp"
#include "cli/run_inputs.hpp"
#include "cli/staged_directory.hpp"
#include "compiler/literal.hpp"
#include "import/gltf_asset.hpp"
#include "import/model_import.hpp"
#include "import/mtlx_import.hpp"

namespace wg {

namespace {

constexpr const char* kImportUsage = R"(Usage: weathergen import MODEL.gltf|MODEL.glb|DOCUMENT.mtlx -o DIR [options]

Writes one material graph per glTF or MaterialX material (MODEL_MATERIAL.json), the
images beside them (MODEL_imageN.png|jpg) and MODEL.import.json, the index from each
material to its graph. Nothing is written if the model or document has an error.

Options:
)";

struct ImportOptions {
  std::string model, outputDir, preset = "rock", presetMap;
  bool json = false, quiet = false, help = false, presetGiven = false, displacement = false;
  std::vector<std::string> searchPath;  // MaterialX only
  mtlx::MissingImages missingImages = mtlx::MissingImages::Error;
};

OptionTable importOptionTable(ImportOptions& o) {
  return {.options = {
              {"--output", "-o", "DIR", "where to write (created if missing)", storeValue(o.outputDir)},
              {"--weather-preset", "", "NAME",
               "every material's weather: rock, terrain, foliage, river,\nroad or none (default: rock)",
               [&o](const std::string& v) {
                 if (std::string e = checkWeatherPresetName(v); !e.empty()) return e;
                 o.preset = v;
                 o.presetGiven = true;
                 return std::string();
               }},
              {"--preset-map", "", "RULES",
               "per material: 'GLOB=PRESET,...' matched against material\n"
               "names in order, e.g. '*Ground*=terrain,*Leaf*=foliage,*=rock';\n"
               "a material no rule matches gets no weather",
               [&o](const std::string& v) { return setPresetMap(v, o.presetMap); }},
              {"--snow-displacement", "", "",
               "keep the presets' snow displacement (off by default: it moves\n"
               "vertices along their normals, which tears meshes that are\n"
               "split at hard edges, as most glTF meshes are)",
               storeFlag(o.displacement)},
              {"--search-path", "", "DIR",
               "MaterialX: a folder to find images and xi:includes in, after\n"
               "the document's own (repeatable); nothing outside them is read",
               [&o](const std::string& v) {
                 std::error_code ec;
                 if (!std::filesystem::is_directory(v, ec)) return "--search-path '" + quoteUserText(v) + "' is not a folder";
                 o.searchPath.push_back(v);
                 return std::string();
               }},
              {"--missing-images", "", "MODE",
               "MaterialX: error (default): a missing image is an error;\n"
               "placeholder: the placeholder image, with a warning",
               [&o](const std::string& v) {
                 if (v != "error" && v != "placeholder") return "--missing-images takes error or placeholder, not '" + quoteUserText(v) + "'";
                 o.missingImages = v == "error" ? mtlx::MissingImages::Error : mtlx::MissingImages::Placeholder;
                 return std::string();
               }},
              {"--diagnostics", "", "text|json", "diagnostic format on stderr (default: text)",
               [&o](const std::string& v) { return setDiagnosticsFormat(v, o.json); }},
              {"--quiet", "-q", "", "no summary line (on stdout)", storeFlag(o.quiet)},
              {"--help", "-h", "", "", storeFlag(o.help)},
          },
          .operand = [&o](const std::string& model) {
            if (!o.model.empty())
              return "import takes one model; got '" + quoteUserText(o.model) + "' and '" + quoteUserText(model) + "'";
            o.model = model;
            return std::string();
          },
          .dashIsOperand = false,
          .unknownSuffix = "; run 'weathergen import --help'"};
}

// Returns -1 when parsing succeeded, else the exit code.
int parseImportOptions(int argc, char** argv, ImportOptions& o) {
  const OptionParseResult parsed = parseOptions(importOptionTable(o), argc, argv, 2);
  if (parsed.status == OptionParse::Failed) return usageError(parsed.error, o.json);
  if (o.help) return -1;
  if (o.model.empty()) return usageError("no model; write 'weathergen import MODEL.gltf -o DIR'", o.json);
  if (o.outputDir.empty()) return usageError("no output directory; pass -o DIR", o.json);
  if (o.presetGiven && !o.presetMap.empty()) return usageError("--weather-preset and --preset-map exclude each other", o.json);
  bool materialX = std::filesystem::path(o.model).extension() == ".mtlx";
  if (!materialX && (!o.searchPath.empty() || o.missingImages != mtlx::MissingImages::Error))
    return usageError("--search-path and --missing-images are for MaterialX documents (.mtlx)", o.json);
  return -1;
}

// The model or document and the files it reads must never be replaced by an output.
std::string replacedInput(const std::vector<std::filesystem::path>& inputs, const std::vector<gltf::ImportedFile>& files,
                          const std::filesystem::path& dir) {
  RunInputs read;
  read.add(inputs);
  std::vector<PlannedOutput> outputs;
  for (const auto& f : files) outputs.push_back({"-o", dir / f.name});
  return read.checkOutputs(outputs);
}

int writeImport(const gltf::Asset& asset, const gltf::ImportedModel& imported, const ImportOptions& o) {
  if (std::string e = replacedInput(asset.inputFiles(), imported.files, o.outputDir); !e.empty())
    return usageError(e, o.json);
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

// Publishes imported files into the output directory, all or none; "" or the error.
std::string publish(const std::vector<gltf::ImportedFile>& files, const std::string& dir) {
  StagedDirectory out(dir);
  for (const auto& f : files)
    if (std::string e = out.stage(f.name, f.bytes); !e.empty()) return e;
  return out.publish();
}

int importMaterialX(const ImportOptions& o) {
  std::string error;
  auto presets = o.presetMap.empty() ? std::optional(gltf::PresetChoice::everywhere(o.preset))
                                     : gltf::PresetChoice::fromMap(o.presetMap, error);
  if (!presets) return usageError(error, o.json);
  DiagnosticList diagnostics;
  auto document = mtlx::loadDocument(o.model, o.searchPath, diagnostics);
  std::optional<mtlx::ImportedDocument> imported;
  if (document) imported = mtlx::importDocument(*document, {*presets, o.missingImages, o.displacement}, diagnostics);
  printDiagnostics(diagnostics.items(), o.json);
  if (!imported) return kExitBadInput;
  std::vector<std::filesystem::path> read = document->inputFiles();
  read.insert(read.end(), imported->imagesRead.begin(), imported->imagesRead.end());
  if (std::string e = replacedInput(read, imported->files, o.outputDir); !e.empty()) return usageError(e, o.json);
  if (std::string e = publish(imported->files, o.outputDir); !e.empty()) return usageError(e, o.json);
  if (!o.quiet)
    std::printf("import: %zu material graph(s) and %zu image(s) from %s into %s (index: %s)\n", imported->materialGraphs.size(),
                imported->imageCount, quoteUserText(o.model, 200).c_str(), quoteUserText(o.outputDir, 200).c_str(),
                imported->indexFile.c_str());
  return kExitOk;
}

}  // namespace

int runImportCommand(int argc, char** argv) {
  ImportOptions o;
  if (int code = parseImportOptions(argc, argv, o); code >= 0) return code;
  if (o.help) {
    ImportOptions scratch;  // the listing reads only the rows' names and help
    std::fputs((kImportUsage + formatOptionList(importOptionTable(scratch))).c_str(), stdout);
    return kExitOk;
  }
  std::string error;
  if (std::filesystem::path(o.model).extension() == ".mtlx") return importMaterialX(o);
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
