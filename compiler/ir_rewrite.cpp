#include "compiler/ir_rewrite.hpp"

namespace wg {

void reorderNodes(IrGraph& graph, const std::vector<std::uint32_t>& order) {
  std::vector<std::uint32_t> newIndex(graph.nodes.size(), kRemovedNode);
  for (std::uint32_t i = 0; i < order.size(); ++i) newIndex[order[i]] = i;
  std::vector<IrNode> nodes;
  nodes.reserve(order.size());
  for (std::uint32_t old : order) nodes.push_back(std::move(graph.nodes[old]));
  graph.nodes = std::move(nodes);
  forEachOperand(graph, [&](Operand& operand) {
    if (operand.kind == Operand::Kind::Node) operand.node = newIndex[operand.node];
  });
}

}  // namespace wg
