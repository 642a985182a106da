// One glTF 2.0 metallic-roughness material as a weathergen material graph, with the
// meaning the glTF specification gives each property (docs/gltf-import.md):
//   baseColor = baseColorFactor x baseColorTexture (sRGB) x COLOR_0
//   metallic, roughness = factors x metallicRoughnessTexture (B, G)
//   normal = normalTexture (tangent space) with its scale
//   ambientOcclusion = 1 + strength x (occlusionTexture.R - 1)
//   emissive = emissiveFactor x emissiveTexture (sRGB) x KHR_materials_emissive_strength
// plus alphaMode/alphaCutoff, doubleSided, texCoord 0 and 1, samplers and
// KHR_texture_transform. Factors become material parameters, so engines can tune them.
#pragma once
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "compiler/diagnostic.hpp"
#include "import/gltf_asset.hpp"

namespace wg::gltf {

struct GraphNaming {
  std::string name;                     // the graph's name and file stem
  std::vector<std::string> imageFiles;  // per glTF image: the file the graph reads
  std::string weatherPreset;            // a preset name, "none" for no weather
  // Snow displacement moves vertices along their normals. glTF meshes split vertices
  // at hard edges, where that tears faces apart, so it is off unless asked for.
  bool snowDisplacement = false;
};

// The graph of material `index`, or of the glTF default material when index < 0.
// Unmapped extensions are WG5101 warnings; bad sampler enums are WG5002 errors.
nlohmann::ordered_json materialGraph(const Asset& asset, int index, const GraphNaming& naming, DiagnosticList& diagnostics);

// The texture coordinate sets material `index` samples (bit 0: set 0, bit 1: set 1).
unsigned texCoordSetsUsed(const tinygltf::Model& model, int index);

}  // namespace wg::gltf
