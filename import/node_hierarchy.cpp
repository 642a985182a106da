#include "import/node_hierarchy.hpp"

#include <algorithm>
#include <cstdint>

namespace wg::gltf {

namespace {
constexpr int kNoParent = -1;

std::string describeCycle(const std::vector<int>& parent, int start) {
  std::string path = std::to_string(start);
  for (int n = parent[start], steps = 0; n != start && steps < 8; n = parent[n], ++steps) path = std::to_string(n) + " -> " + path;
  return std::to_string(start) + " -> ... -> " + path;
}
}  // namespace

bool checkNodeHierarchy(const Asset& asset, DiagnosticList& diags) {
  const auto& nodes = asset.model.nodes;
  std::vector<int> parent(nodes.size(), kNoParent);
  for (std::size_t p = 0; p < nodes.size(); ++p)
    for (std::size_t c = 0; c < nodes[p].children.size(); ++c) {
      int child = nodes[p].children[c];
      if (parent[child] == kNoParent) {
        parent[child] = static_cast<int>(p);
        continue;
      }
      diags.report(DiagCode::GltfNodeHierarchy, asset.locate("/nodes/" + std::to_string(p) + "/children/" + std::to_string(c)),
                   {"node " + std::to_string(child) + " has two parents, nodes " + std::to_string(parent[child]) + " and " +
                    std::to_string(p)});
      return false;
    }
  // With one parent each, climbing from a node ends at a root or runs into a cycle.
  // Nodes proven to reach a root are remembered, so the whole check is linear.
  enum : std::uint8_t { Unknown, ReachesRoot, OnPath };
  std::vector<std::uint8_t> state(nodes.size(), Unknown);
  std::vector<int> path;
  for (std::size_t n = 0; n < nodes.size(); ++n) {
    path.clear();
    int at = static_cast<int>(n);
    while (at != kNoParent && state[at] == Unknown) {
      state[at] = OnPath;
      path.push_back(at);
      at = parent[at];
    }
    if (at != kNoParent && state[at] == OnPath) {
      diags.report(DiagCode::GltfNodeHierarchy, asset.locate("/nodes/" + std::to_string(at)),
                   {"node " + std::to_string(at) + " is its own ancestor (" + describeCycle(parent, at) + ")"});
      return false;
    }
    for (int p : path) state[p] = ReachesRoot;
  }
  for (std::size_t s = 0; s < asset.model.scenes.size(); ++s)
    for (std::size_t i = 0; i < asset.model.scenes[s].nodes.size(); ++i) {
      const auto& roots = asset.model.scenes[s].nodes;
      int root = roots[i];
      if (std::find(roots.begin(), roots.begin() + static_cast<std::ptrdiff_t>(i), root) != roots.begin() + static_cast<std::ptrdiff_t>(i)) {
        diags.report(DiagCode::GltfNodeHierarchy, asset.locate("/scenes/" + std::to_string(s) + "/nodes/" + std::to_string(i)),
                     {"scene " + std::to_string(s) + " lists node " + std::to_string(root) + " twice"});
        return false;
      }
      if (parent[root] == kNoParent) continue;
      diags.report(DiagCode::GltfNodeHierarchy, asset.locate("/scenes/" + std::to_string(s) + "/nodes/" + std::to_string(i)),
                   {"scene " + std::to_string(s) + " lists node " + std::to_string(root) + ", which is a child of node " +
                    std::to_string(parent[root])});
      return false;
    }
  return true;
}

}  // namespace wg::gltf
