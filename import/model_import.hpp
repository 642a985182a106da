// `weathergen import`: a checked glTF asset -> one material graph per glTF material,
// its images as the file stored them, and MODEL.import.json indexing both. The result
// is bytes in memory; the CLI publishes it all at once or not at all. Names are
// sanitised and depend only on the file's contents, so re-importing gives identical
// bytes, and a .gltf, its .glb and its embedded form give identical graphs.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "compiler/diagnostic.hpp"
#include "import/gltf_asset.hpp"
#include "import/model_geometry.hpp"
#include "import/preset_map.hpp"

namespace wg::gltf {

struct ImportedFile {
  std::string name;  // file name inside the output directory
  std::string bytes;
};

struct ImportedModel {
  std::vector<ImportedFile> files;
  std::string indexFile;  // MODEL.import.json
  // Graph file per glTF material index; defaultGraph for primitives without one.
  std::vector<std::string> materialGraphs;
  std::string defaultGraph;  // "" unless some primitive has no material
  std::vector<std::string> imageFiles;  // per glTF image index
};

struct ImportSettings {
  PresetChoice presets = PresetChoice::everywhere("rock");
  bool snowDisplacement = false;  // see GraphNaming::snowDisplacement
  // Metres per model unit (render's --model-scale; glTF says 1): only to warn (WG5103)
  // when the model's size suggests other units. The graphs do not depend on it.
  float metresPerUnit = 1.f;
};

std::optional<ImportedModel> importModel(const Asset& asset, const ModelGeometry& geometry, const ImportSettings& settings,
                                         DiagnosticList& diagnostics);

// Graph file stems MODEL_MATERIAL, one per material name (docs/gltf-import.md): names
// that collide, ignoring case, all take their material index as a suffix.
std::vector<std::string> materialStems(const std::vector<std::string>& names, const std::string& modelStem);

// A file-name-safe form of any text: [A-Za-z0-9_-], at most 48 characters, never empty.
std::string fileSafeName(std::string_view text, std::string_view fallback);

// The model's file stem made safe (fileSafeName), and marked (name_mark.hpp) when it is a
// name Windows reserves: "CON.gltf" writes CON_hXXXXXXXX.import.json, not CON.import.json.
std::string modelFileStem(const std::string& modelPath);

}  // namespace wg::gltf
