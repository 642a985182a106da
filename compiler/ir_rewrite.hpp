// Shared mechanics for passes: visiting every operand, and renumbering nodes.
#pragma once
#include <cstdint>
#include <vector>

#include "compiler/ir.hpp"

namespace wg {

inline constexpr std::uint32_t kRemovedNode = 0xFFFFFFFFu;

// Calls f(Operand&) on every node input and every output binding.
template <typename F>
void forEachOperand(IrGraph& graph, F&& f) {
  for (auto& node : graph.nodes)
    for (auto& operand : node.inputs) f(operand);
  graph.forEachRoot(f);
}

// Keeps the nodes listed in `order` (old indices, already topologically sorted),
// in that order, and rewrites every reference.
void reorderNodes(IrGraph& graph, const std::vector<std::uint32_t>& order);

}  // namespace wg
