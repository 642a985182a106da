// Removes nodes that no output depends on. Nodes are topologically ordered, so one
// backward sweep marks everything reachable.
#include "compiler/ir_rewrite.hpp"
#include "compiler/pass_pipeline.hpp"

namespace wg {

void eliminateDeadNodes(IrGraph& graph) {
  std::vector<bool> live(graph.nodes.size(), false);
  graph.forEachRoot([&](const Operand& operand) {
    if (operand.kind == Operand::Kind::Node) live[operand.node] = true;
  });
  for (std::size_t i = graph.nodes.size(); i-- > 0;) {
    if (!live[i]) continue;
    for (const auto& operand : graph.nodes[i].inputs)
      if (operand.kind == Operand::Kind::Node) live[operand.node] = true;
  }
  std::vector<std::uint32_t> order;
  for (std::uint32_t i = 0; i < graph.nodes.size(); ++i)
    if (live[i]) order.push_back(i);
  if (order.size() != graph.nodes.size()) reorderNodes(graph, order);
}

}  // namespace wg
