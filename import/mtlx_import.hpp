// `weathergen import FILE.mtlx`: a checked MaterialX document -> one material graph per
// surfacematerial, the images they read (found through fileprefix and the search path,
// copied as the files store them), and DOCUMENT.import.json indexing materials, images
// and looks. Like glTF import, the result is bytes in memory that the CLI publishes all
// at once or not at all, and names depend only on the document's contents.
#pragma once
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "compiler/diagnostic.hpp"
#include "import/model_import.hpp"
#include "import/mtlx_document.hpp"
#include "import/preset_map.hpp"

namespace wg::mtlx {

// What a missing image becomes: an error, or the placeholder image
// (docs/materialx-import.md), for pipelines that fetch textures later.
enum class MissingImages { Error, Placeholder };

struct ImportSettings {
  gltf::PresetChoice presets = gltf::PresetChoice::everywhere("rock");
  MissingImages missingImages = MissingImages::Error;
  bool snowDisplacement = false;  // see GraphNaming::snowDisplacement
};

struct ImportedDocument {
  std::vector<gltf::ImportedFile> files;
  std::string indexFile;                    // DOCUMENT.import.json
  std::vector<std::string> materialGraphs;  // in document order
  std::size_t imageCount = 0;               // image files written, the placeholder included
  std::vector<std::filesystem::path> imagesRead;  // resolved, for the check that no output replaces one
};

std::optional<ImportedDocument> importDocument(const Document& document, const ImportSettings& settings,
                                               DiagnosticList& diagnostics);

// The placeholder: a 1x1 PNG of (128, 128, 255), flat in a normal map, 0.5 in a float
// channel and a clear lavender in a colour.
std::string_view placeholderPng();

}  // namespace wg::mtlx
