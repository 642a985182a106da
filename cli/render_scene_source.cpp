#include "cli/render_scene_source.hpp"

#include <filesystem>

#include "cli/commands.hpp"
#include "cli/diagnostic_output.hpp"
#include "cli/model_scene.hpp"
#include "compiler/literal.hpp"
#include "host/scene/graph_path.hpp"
#include "host/scene/preview_stand.hpp"
#include "import/model_import.hpp"

namespace wg {

namespace {

int bundledScene(const std::string& name, SceneSource& source) {
  auto scene = scene::makeScene(name);
  if (!scene) return usageError("unknown scene '" + quoteUserText(name) + "' (scenes: " + sceneNameList() + ")");
  source = {std::move(*scene), {}};
  return kExitOk;
}

// The stand is named after the graph file ("stand-rock"), which names its --frames
// pictures: made file-safe as an imported model's name is, so no control character,
// invalid UTF-8 or overlong name reaches a file name.
int materialOnStand(const std::string& graphPath, SceneSource& source) {
  if (!scene::isGraphFilePath(graphPath))
    return usageError("--material takes a graph file ending in .json, not '" + quoteUserText(graphPath) + "'");
  std::string name = "stand-" + gltf::fileSafeName(std::filesystem::path(graphPath).stem().string(), "graph");
  source = {scene::previewStand(graphPath, name), {graphPath}};
  return kExitOk;
}

// Materials get the --preset-map rules, or rock; --weather-preset still replaces them all.
int modelOnStage(const RenderOptions& o, SceneSource& source) {
  std::string error;
  auto presets = o.presetMap.empty() ? std::optional(gltf::PresetChoice::everywhere("rock")) : gltf::PresetChoice::fromMap(o.presetMap, error);
  if (!presets) return usageError(error);
  ModelScene model;
  if (int e = loadModelScene(o.modelPath, {*presets, o.snowDisplacement}, o.modelScale, model)) return e;
  source = {std::move(model.scene), std::move(model.inputFiles), std::move(model.graphs), std::move(model.origins)};
  return kExitOk;
}

}  // namespace

std::string checkOneSceneSource(const RenderOptions& o) {
  int named = !o.sceneName.empty() + !o.materialPath.empty() + !o.modelPath.empty();
  if (named == 1) return "";
  if (named == 0)
    return "nothing to render; pass --scene NAME (" + sceneNameList() + "), --material GRAPH.json or --model MODEL.gltf";
  return "--scene, --material and --model exclude each other";
}

int chooseScene(const RenderOptions& o, SceneSource& source) {
  if (!o.materialPath.empty()) return materialOnStand(o.materialPath, source);
  if (!o.modelPath.empty()) return modelOnStage(o, source);
  return bundledScene(o.sceneName, source);
}

}  // namespace wg
