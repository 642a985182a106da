// Where `render` gets its scene: --scene (a bundled scene), --material (a graph on the
// preview stand) or, later, --model. Everything after this choice is shared.
#pragma once
#include <string>
#include <vector>

#include <memory>

#include "cli/imported_origin.hpp"
#include "cli/render_options.hpp"
#include "cli/temporary_directory.hpp"
#include "host/scene/scene.hpp"

namespace wg {

struct SceneSource {
  scene::Scene scene;
  // The files the scene was built from, which --watch polls besides its materials' own
  // inputs (SceneRenderer::materialInputFiles): --material's graph; a model's files.
  std::vector<std::string> inputFiles;
  // --model: where its imported graphs live while the scene is drawn.
  std::shared_ptr<TemporaryDirectory> graphFolder;
  std::vector<ImportedOrigin> origins;  // --model: what each file in graphFolder was made from
};

// "" when the options name exactly one source, else a usage message.
std::string checkOneSceneSource(const RenderOptions& options);

// Builds the scene the options name (not the snowfield, which animates itself).
// Returns kExitOk, or the exit code after printing the error.
int chooseScene(const RenderOptions& options, SceneSource& source);

}  // namespace wg
