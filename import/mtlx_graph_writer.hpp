// One MaterialX material (a surfacematerial and its surface shader) as a weathergen
// material graph (docs/materialx-import.md):
//   gltf_pbr, UsdPreviewSurface: their inputs map one to one onto the UE4 model;
//   standard_surface, open_pbr_surface: base colour x weight, metalness, specular
//     roughness, emission colour x weight, opacity and normal, as MaterialX's own
//     translation to gltf_pbr maps them; other lobes are WG5301 warnings.
// The node graphs feeding the shader become graph nodes, one MaterialX node to one or a
// few graph ops; a node the import does not map is WG5204.
#pragma once
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "compiler/diagnostic.hpp"
#include "import/mtlx_document.hpp"

namespace wg::mtlx {

// The file name the graph reads an image from, given the <input name="file"> element and
// the path the document names (fileprefix applied); nullopt after reporting when it
// cannot be had.
using ImageFiles = std::function<std::optional<std::string>(pugi::xml_node fileInput, const std::string& path)>;

struct GraphNaming {
  std::string name;           // the graph's name and file stem
  std::string description;
  std::string weatherPreset;  // a preset name, "none" for no weather
  bool snowDisplacement = false;  // off, as glTF import has it, unless asked for
};

// Graph nodes one import may write, all materials together: materials sharing one large
// node graph each get their own copy of it, so a small document could ask for gigabytes.
constexpr std::size_t kMaxImportGraphNodes = 400000;

// The graph of `material` (a <surfacematerial>), or nullopt after reporting its errors.
// `nodesLeft` (of kMaxImportGraphNodes) goes down by the graph's nodes; 0 once a limit is reached.
std::optional<nlohmann::ordered_json> materialGraph(const Document& document, pugi::xml_node material,
                                                    const GraphNaming& naming, const ImageFiles& images,
                                                    std::size_t& nodesLeft, DiagnosticList& diagnostics);

// The shader node a <surfacematerial> uses, or an empty node.
pugi::xml_node surfaceShader(const Document& document, pugi::xml_node material);

}  // namespace wg::mtlx
