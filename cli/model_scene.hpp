// `render --model`: a glTF model stood on the stage (host/scene/stage.hpp), every
// mesh primitive drawn with its node transform and its imported, weathered material.
// The materials are imported into a private temporary directory that lives as long as
// the scene needs its graphs.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "cli/imported_origin.hpp"
#include "cli/temporary_directory.hpp"
#include "import/model_import.hpp"
#include "host/scene/scene.hpp"

namespace wg {

struct ModelScene {
  scene::Scene scene;
  std::vector<std::string> inputFiles;  // the model and the files it reads, for --watch
  std::shared_ptr<TemporaryDirectory> graphs;
  std::vector<ImportedOrigin> origins;
};

// Returns kExitOk, or prints the diagnostics and returns the exit code.
// `scale` is metres per model unit, applied above every node.
int loadModelScene(const std::string& modelPath, const gltf::ImportSettings& settings, float scale, ModelScene& out);

}  // namespace wg
