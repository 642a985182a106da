#include "cli/render_scene_source.hpp"

#include <filesystem>

#include "cli/commands.hpp"
#include "cli/diagnostic_output.hpp"
#include "compiler/literal.hpp"
#include "runtime/scene/graph_path.hpp"
#include "runtime/scene/preview_stand.hpp"

namespace wg {

namespace {

int bundledScene(const std::string& name, SceneSource& source) {
  auto scene = scene::makeScene(name);
  if (!scene) {
    std::string names;
    for (auto n : scene::sceneNames()) names += (names.empty() ? "" : ", ") + std::string(n);
    return usageError("unknown scene '" + quoteUserText(name) + "' (scenes: " + names + ", snowfield)");
  }
  source = {std::move(*scene), {}};
  return kExitOk;
}

// The stand is named after the graph file ("stand-rock"), which names its frames.
int materialOnStand(const std::string& graphPath, SceneSource& source) {
  if (!scene::isGraphFilePath(graphPath))
    return usageError("--material takes a graph file ending in .json, not '" + quoteUserText(graphPath) + "'");
  std::string name = "stand-" + std::filesystem::path(graphPath).stem().string();
  source = {scene::previewStand(graphPath, name), {graphPath}};
  return kExitOk;
}

}  // namespace

std::string checkOneSceneSource(const RenderOptions& o) {
  int named = !o.sceneName.empty() + !o.materialPath.empty();
  if (named == 1) return "";
  if (named == 0) return "nothing to render; pass --scene NAME (valley, rocks, river, road or snowfield) or --material GRAPH.json";
  return "--scene and --material exclude each other";
}

int chooseScene(const RenderOptions& o, SceneSource& source) {
  if (!o.materialPath.empty()) return materialOnStand(o.materialPath, source);
  return bundledScene(o.sceneName, source);
}

}  // namespace wg
