// The options of `weathergen render`, as parsed from the command line.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "cli/sample_count.hpp"
#include "host/scene/orbit_camera.hpp"
#include "host/scene_renderer.hpp"

namespace wg {

struct RenderOptions {
  // Where the scene comes from: exactly one of these (render_scene_source.hpp).
  std::string sceneName;     // --scene: a bundled scene
  std::string materialPath;  // --material: a graph file on the preview stand
  std::string modelPath;     // --model: a glTF model, its materials imported and weathered
  std::string presetMap;     // --preset-map: the model materials' presets (docs/gltf-import.md)
  float modelScale = 1.f;    // --model-scale: metres per model unit (glTF says 1)
  bool snowDisplacement = false;  // --snow-displacement, as import takes it
  std::string camera;        // --camera: a preset name, or orbit:... (then `orbit` is set)
  std::optional<scene::Orbit> orbit;
  std::string output, timelinePath, framesDir, aov = "lit", device, graphsDir;
  std::optional<std::string> weatherPreset;
  std::vector<std::string> weatherLists;
  RenderRequest request;  // size, backend, shadows, precipitation
  unsigned samples = kDefaultColourSamples;  // --samples: the lit pass's MSAA, 1 for none
  double step = 300.0;    // --timeline's simulation step, seconds
  bool validation = false, quiet = false;
  bool watch = false;
  std::optional<unsigned> watchRenders;  // --watch-renders: stop after this many
};

// What --scene takes: "valley, rocks, river, road or snowfield" (the scene table's
// names, then the interactive snowfield).
std::string sceneNameList();

// Parses argv from `first`. Returns an exit code when the command is done (--help, or a
// usage error already printed), nullopt to go on.
std::optional<int> parseRenderOptions(int argc, char** argv, int first, RenderOptions& options);

}  // namespace wg
