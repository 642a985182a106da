#include "cli/model_scene.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include <glm/gtc/matrix_transform.hpp>

#include "cli/commands.hpp"
#include "cli/diagnostic_output.hpp"
#include "compiler/literal.hpp"
#include "import/gltf_asset.hpp"
#include "import/model_geometry.hpp"
#include "import/model_import.hpp"
#include "host/scene/stage.hpp"

namespace wg {

namespace {

// glTF without NORMAL asks for flat normals (glTF 2.0, 3.7.2.1): every triangle gets
// its own three vertices.
void unweldFlat(scene::Mesh& mesh) {
  scene::Mesh flat;
  bool uv1 = !mesh.texcoords1.empty();
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    std::uint32_t v[3] = {mesh.indices[t], mesh.indices[t + 1], mesh.indices[t + 2]};
    glm::vec3 n = glm::cross(mesh.positions[v[1]] - mesh.positions[v[0]], mesh.positions[v[2]] - mesh.positions[v[0]]);
    n = glm::length(n) > 0.f ? glm::normalize(n) : glm::vec3(0.f, 1.f, 0.f);
    for (std::uint32_t i : v) {
      flat.indices.push_back(scene::addVertex(flat, mesh.positions[i], n, mesh.texcoords[i], mesh.colors[i]));
      if (uv1) flat.texcoords1.push_back(mesh.texcoords1[i]);
    }
  }
  mesh = std::move(flat);
}

// Our meshes' tangents put the bitangent along +v; glTF's point it along -v (image
// up, glTF 2.0 3.9.3), which is what its normal maps encode.
void generateGltfTangents(scene::Mesh& mesh) {
  scene::computeTangents(mesh);
  for (auto& t : mesh.tangents) t.w = -t.w;
}

scene::Mesh toMesh(const gltf::ModelPrimitive& p) {
  scene::Mesh mesh;
  std::size_t n = p.positions.size();
  mesh.positions = p.positions;
  mesh.normals = p.normals;
  mesh.texcoords = p.texcoords0.empty() ? std::vector<glm::vec2>(n, glm::vec2(0.f)) : p.texcoords0;
  mesh.texcoords1 = p.texcoords1;
  mesh.colors = p.colors.empty() ? std::vector<glm::vec4>(n, glm::vec4(1.f)) : p.colors;
  mesh.indices = p.indices;
  if (mesh.normals.empty()) unweldFlat(mesh);
  for (auto& normal : mesh.normals)
    if (glm::length(normal) > 0.f) normal = glm::normalize(normal);
  if (p.tangents.empty() || mesh.normals.size() != p.normals.size()) generateGltfTangents(mesh);
  else mesh.tangents = p.tangents;
  return mesh;
}

std::vector<std::string> modelInputFiles(const gltf::Asset& asset) {
  std::vector<std::string> files;
  for (const auto& f : asset.inputFiles()) files.push_back(f.string());
  return files;
}

std::string writeImported(const gltf::ImportedModel& imported, const std::filesystem::path& dir) {
  for (const auto& f : imported.files) {
    std::ofstream out(dir / f.name, std::ios::binary);
    if (!out.write(f.bytes.data(), static_cast<std::streamsize>(f.bytes.size())))
      return "cannot write the imported graphs to '" + (dir / f.name).string() + "'";
  }
  return "";
}

std::vector<scene::SceneObject> modelObjects(const gltf::ModelGeometry& geometry, const gltf::ImportedModel& imported,
                                             const std::filesystem::path& dir) {
  std::vector<scene::SceneObject> objects;
  for (std::size_t i = 0; i < geometry.primitives.size(); ++i) {
    const auto& p = geometry.primitives[i];
    if (p.indices.empty()) continue;
    scene::SceneObject o;
    o.name = "primitive" + std::to_string(i) + ":" + quoteUserText(p.name);
    o.graph = (dir / (p.material >= 0 ? imported.materialGraphs[p.material] : imported.defaultGraph)).string();
    o.mesh = toMesh(p);
    o.model = p.transform;
    objects.push_back(std::move(o));
  }
  return objects;
}

// Scales the model to metres and stands it at the origin: its lowest point on y = 0 and
// its footprint centred, wherever the file placed it, so the weather's height terms see
// the same ground for every model. False when the placed model is larger than a stage
// can frame (its ground, 4 times as wide, must stay far inside float range).
bool standAtOrigin(std::vector<scene::SceneObject>& objects, float scale) {
  constexpr float kLargestExtent = 1e6f;  // metres
  scene::Bounds b;
  glm::mat4 scaled = glm::scale(glm::mat4(1.f), glm::vec3(scale));
  for (const auto& o : objects) b.include(scene::bounds(o.mesh, scaled * o.model));
  glm::vec3 size = b.max - b.min;
  if (!(std::max({size.x, size.y, size.z}) <= kLargestExtent)) return false;
  glm::mat4 place = glm::translate(glm::mat4(1.f), -glm::vec3(0.5f * (b.min.x + b.max.x), b.min.y, 0.5f * (b.min.z + b.max.z)));
  for (auto& o : objects) o.model = place * scaled * o.model;
  return true;
}

std::string nameInParentheses(const std::string& name, const char* unnamed) {
  return " (" + (name.empty() ? std::string(unnamed) : quoteUserText(name, 80)) + ")";
}

// A data: URI is the image itself, not a name.
std::string externalUri(const std::string& uri) { return uri.starts_with("data:") ? "" : uri; }

// Each imported graph and image, and the glTF object it was made from.
std::vector<ImportedOrigin> importedOrigins(const gltf::Asset& asset, const gltf::ImportedModel& imported,
                                            const std::filesystem::path& dir) {
  std::vector<ImportedOrigin> origins;
  for (std::size_t i = 0; i < imported.materialGraphs.size(); ++i) {
    const std::string pointer = appendPointer("/materials", i);
    origins.push_back({(dir / imported.materialGraphs[i]).string(), asset.locate(pointer),
                       "material " + std::to_string(i) + nameInParentheses(asset.model.materials[i].name, "unnamed")});
  }
  if (!imported.defaultGraph.empty())
    origins.push_back({(dir / imported.defaultGraph).string(), asset.locate("/meshes"), "the default material of primitives without one"});
  for (std::size_t i = 0; i < imported.imageFiles.size(); ++i) {
    origins.push_back({(dir / imported.imageFiles[i]).string(), asset.locate(appendPointer("/images", i)),
                       "image " + std::to_string(i) + nameInParentheses(externalUri(asset.model.images[i].uri), "embedded")});
  }
  return origins;
}

int modelError(const gltf::Asset& asset, const std::string& message, const std::string& hint) {
  DiagnosticList list;
  list.report(DiagCode::GltfInvalidData, asset.locate(""), {message, hint});
  printDiagnostics(list.items(), false);
  return kExitBadInput;
}

}  // namespace

int loadModelScene(const std::string& modelPath, const gltf::ImportSettings& settings, float scale, ModelScene& out) {
  DiagnosticList diagnostics;
  auto asset = gltf::loadAsset(modelPath, diagnostics);
  std::optional<gltf::ModelGeometry> geometry;
  if (asset) geometry = gltf::readModelGeometry(*asset, diagnostics);
  std::optional<gltf::ImportedModel> imported;
  gltf::ImportSettings scaled = settings;
  scaled.metresPerUnit = scale;
  if (geometry) imported = gltf::importModel(*asset, *geometry, scaled, diagnostics);
  printDiagnostics(diagnostics.items(), false);
  if (!imported) return kExitBadInput;
  try {
    out.graphs = TemporaryDirectory::create("weathergen-model");
  } catch (const std::exception& e) {
    return usageError(std::string(e.what()) + " (set TMPDIR to a writable directory)");
  }
  if (std::string e = writeImported(*imported, out.graphs->path()); !e.empty()) return usageError(e + " (check TMPDIR)");
  std::vector<scene::SceneObject> objects = modelObjects(*geometry, *imported, out.graphs->path());
  if (objects.empty())
    return modelError(*asset, "the model's scene draws no triangles", "render a model whose scene holds at least one triangle mesh");
  if (!standAtOrigin(objects, scale))
    return modelError(*asset, "the model spans more than 1000 km at --model-scale " + std::to_string(scale),
                      "pass a smaller --model-scale (0.001 for millimetres), or re-export the model with sensible coordinates");
  out.scene = scene::stageAround("model-" + gltf::fileSafeName(std::filesystem::path(modelPath).stem().string(), "model"), std::move(objects));
  out.inputFiles = modelInputFiles(*asset);
  out.origins = importedOrigins(*asset, *imported, out.graphs->path());
  return kExitOk;
}

}  // namespace wg
