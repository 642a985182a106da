#include "import/model_import.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <tuple>

#include "compiler/json_text.hpp"
#include "compiler/name_mark.hpp"
#include "import/material_graph_writer.hpp"

namespace wg::gltf {

namespace {

using Json = nlohmann::ordered_json;

std::string lowered(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

std::vector<std::string> graphStems(const tinygltf::Model& model, const std::string& modelStem) {
  std::vector<std::string> names;
  for (const auto& material : model.materials) names.push_back(material.name);
  return materialStems(names, modelStem);
}

}  // namespace

// MODEL_MATERIAL; names that collide (ignoring case, for case-insensitive
// file systems) all take their material index as a suffix, so no name depends on order.
// A suffixed stem can meet another material's own name ("Red", "Red", "Red_0"), so this
// repeats; a stem is suffixed at most once, so it ends. Two suffixed stems never meet:
// the digits after their last '_' are their distinct indices.
std::vector<std::string> materialStems(const std::vector<std::string>& names, const std::string& modelStem) {
  std::vector<std::string> stems;
  for (std::size_t i = 0; i < names.size(); ++i)
    stems.push_back(modelStem + "_" + fileSafeName(names[i], "material" + std::to_string(i)));
  std::vector<bool> suffixed(stems.size(), false);
  for (bool changed = true; changed;) {
    std::map<std::string, int> uses{{lowered(modelStem + "_default"), 1}};
    for (const auto& stem : stems) ++uses[lowered(stem)];
    changed = false;
    for (std::size_t i = 0; i < stems.size(); ++i)
      if (!suffixed[i] && uses[lowered(stems[i])] > 1) {
        stems[i] += "_" + std::to_string(i);
        suffixed[i] = changed = true;
      }
  }
  return stems;
}

namespace {

// File names are bytes, not always UTF-8; they reach the JSON as replacement characters.
std::string asText(const Json& json) { return jsonText(json, 2) + "\n"; }

// One file per material and per image: bound what a small hostile file can make us write.
constexpr std::size_t kMaxFilesPerKind = 16384;

bool withinFileCounts(const Asset& asset, DiagnosticList& diags) {
  for (auto [what, pointer, count] : {std::tuple{"the material count", "/materials", asset.model.materials.size()},
                                      std::tuple{"the image count", "/images", asset.model.images.size()}})
    if (count > kMaxFilesPerKind) {
      diags.report(DiagCode::ResourceLimit, asset.locate(pointer), {what, std::to_string(count), std::to_string(kMaxFilesPerKind)});
      return false;
    }
  return true;
}

// Sizes a scene of real things spans: a model larger than 100 m or smaller than 1 cm in
// metres is most likely in other units (millimetres, centimetres; or kilometres).
constexpr float kLargestLikelyMetres = 100.f, kSmallestLikelyMetres = 0.01f;

std::string metres(float x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", static_cast<double>(x));
  return text;
}

// WG5103 when the model's size at metresPerUnit suggests other units.
void checkUnits(const Asset& asset, const ModelGeometry& geometry, float metresPerUnit, DiagnosticList& diags) {
  glm::vec3 lo(INFINITY), hi(-INFINITY);
  for (const auto& p : geometry.primitives)
    for (const auto& v : p.positions) {
      glm::vec3 w(p.transform * glm::vec4(v, 1.f));
      lo = glm::min(lo, w);
      hi = glm::max(hi, w);
    }
  if (!(lo.x <= hi.x)) return;  // no vertex
  glm::vec3 size = (hi - lo) * metresPerUnit;
  float extent = std::max({size.x, size.y, size.z});
  if (extent > kLargestLikelyMetres)
    diags.report(DiagCode::GltfModelUnits, asset.locate("/meshes"),
                 {metres(extent), metres(metresPerUnit), "it is probably in millimetres or centimetres",
                  "render it with --model-scale 0.001 (millimetres) or 0.01 (centimetres); the imported graphs are "
                  "the same either way"});
  else if (extent < kSmallestLikelyMetres)
    diags.report(DiagCode::GltfModelUnits, asset.locate("/meshes"),
                 {metres(extent), metres(metresPerUnit), "it is probably in larger units than metres",
                  "render it with a larger --model-scale, e.g. 100; the imported graphs are the same either way"});
}

}  // namespace

std::string fileSafeName(std::string_view text, std::string_view fallback) {
  constexpr std::size_t kMaxLength = 48;
  std::string out;
  for (char c : text) {
    if (out.size() == kMaxLength) break;
    bool safe = std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
    if (safe) out += c;
    else if (!out.empty() && out.back() != '_') out += '_';
  }
  while (!out.empty() && out.back() == '_') out.pop_back();
  if (out.empty() || out.front() == '-') out = std::string(fallback) + (out.empty() ? "" : "_" + out);
  return out;
}

std::string modelFileStem(const std::string& modelPath) {
  const std::string stem = std::filesystem::path(modelPath).stem().string();
  std::string safe = fileSafeName(stem, "model");
  if (isWindowsReservedName(safe)) safe += "_" + nameMark(stem);
  return safe;
}

std::optional<ImportedModel> importModel(const Asset& asset, const ModelGeometry& geometry, const ImportSettings& settings,
                                         DiagnosticList& diags) {
  if (!withinFileCounts(asset, diags)) return std::nullopt;
  const auto& model = asset.model;
  std::string modelStem = modelFileStem(asset.file);
  ImportedModel out;
  GraphNaming naming;
  naming.snowDisplacement = settings.snowDisplacement;
  Json index;
  index["model"] = std::filesystem::path(asset.file).filename().string();
  index["generator"] = std::string("weathergen ") + WEATHERGEN_VERSION;
  index["images"] = Json::array();
  for (std::size_t i = 0; i < model.images.size(); ++i) {
    const EncodedImage& image = asset.images[i];
    std::string file = modelStem + "_image" + std::to_string(i) + image.extension;
    naming.imageFiles.push_back(file);
    out.files.push_back({file, std::string(image.bytes.begin(), image.bytes.end())});
    index["images"].push_back(Json{{"index", i}, {"file", file}, {"width", image.width}, {"height", image.height}});
  }
  std::size_t errorsBefore = diags.items().size();
  auto addGraph = [&](int material, const std::string& stem, const std::string& name) {
    naming.name = stem;
    naming.weatherPreset = settings.presets.presetFor(name);
    out.files.push_back({stem + ".json", asText(materialGraph(asset, material, naming, diags))});
    return Json{{"index", material}, {"name", name}, {"graph", stem + ".json"}, {"weatherPreset", naming.weatherPreset}};
  };
  index["materials"] = Json::array();
  std::vector<std::string> stems = graphStems(model, modelStem);
  for (std::size_t i = 0; i < model.materials.size(); ++i) {
    index["materials"].push_back(addGraph(static_cast<int>(i), stems[i], model.materials[i].name));
    out.materialGraphs.push_back(stems[i] + ".json");
  }
  bool needsDefault = std::any_of(geometry.primitives.begin(), geometry.primitives.end(),
                                  [](const ModelPrimitive& p) { return p.material < 0; });
  if (needsDefault) {
    index["defaultMaterial"] = addGraph(-1, modelStem + "_default", "");
    out.defaultGraph = modelStem + "_default.json";
  }
  checkUnits(asset, geometry, settings.metresPerUnit, diags);
  index["primitives"] = geometry.primitives.size();
  index["triangles"] = geometry.triangleCount;
  DiagnosticList added;
  for (std::size_t i = errorsBefore; i < diags.items().size(); ++i) added.items().push_back(diags.items()[i]);
  if (added.hasErrors()) return std::nullopt;
  out.imageFiles = naming.imageFiles;
  out.indexFile = modelStem + ".import.json";
  out.files.push_back({out.indexFile, asText(index)});
  return out;
}

}  // namespace wg::gltf
