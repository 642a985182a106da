#include "host/scene/graph_path.hpp"

namespace wg::scene {

bool isGraphFilePath(std::string_view graph) {
  constexpr std::string_view kSuffix = ".json";
  return graph.size() >= kSuffix.size() && graph.substr(graph.size() - kSuffix.size()) == kSuffix;
}

std::string graphFilePath(std::string_view graph, const std::string& graphsDirectory) {
  if (isGraphFilePath(graph)) return std::string(graph);
  return graphsDirectory + "/" + std::string(graph) + ".json";
}

}  // namespace wg::scene
