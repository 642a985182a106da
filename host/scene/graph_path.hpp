// Where a SceneObject's graph lives. Bundled scenes name bundled graphs by stem
// ("rock"); previews and imported models name graph files by path. The rule: a value
// ending in ".json" is a file path (absolute, or relative to the working directory);
// anything else is a stem, resolved as <graphsDirectory>/<stem>.json.
#pragma once
#include <string>
#include <string_view>

namespace wg::scene {

bool isGraphFilePath(std::string_view graph);
std::string graphFilePath(std::string_view graph, const std::string& graphsDirectory);

}  // namespace wg::scene
