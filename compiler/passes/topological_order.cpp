// A stable topological order: depth-first post-order from the outputs in field order,
// inputs in port order. It depends only on graph content, never on the order of
// nodes in the file or on their ids. Iterative, so deep graphs cannot overflow.
#include "compiler/ir_rewrite.hpp"
#include "compiler/pass_pipeline.hpp"

namespace wg {

std::vector<std::uint32_t> canonicalNodeOrder(const IrGraph& graph) {
  std::vector<bool> visited(graph.nodes.size(), false);
  std::vector<std::uint32_t> order;
  order.reserve(graph.nodes.size());
  std::vector<std::pair<std::uint32_t, std::size_t>> stack;
  std::vector<Operand> roots;
  graph.forEachRoot([&](const Operand& o) { roots.push_back(o); });
  for (const auto& root : roots) {
    if (root.kind != Operand::Kind::Node || visited[root.node]) continue;
    visited[root.node] = true;
    stack.push_back({root.node, 0});
    while (!stack.empty()) {
      auto& [node, next] = stack.back();
      const auto& inputs = graph.nodes[node].inputs;
      if (next < inputs.size()) {
        const Operand& operand = inputs[next++];
        if (operand.kind == Operand::Kind::Node && !visited[operand.node]) {
          visited[operand.node] = true;
          stack.push_back({operand.node, 0});
        }
      } else {
        order.push_back(node);
        stack.pop_back();
      }
    }
  }
  return order;
}

void orderTopologically(IrGraph& graph) {
  reorderNodes(graph, canonicalNodeOrder(graph));  // also drops anything unreachable
}

}  // namespace wg
