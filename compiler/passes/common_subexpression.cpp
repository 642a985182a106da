// Common-subexpression elimination: nodes with the same op, settings and operands
// (after earlier merges) are one node. Graph content, not spelling, decides.
#include <bit>
#include <string>
#include <unordered_map>

#include "compiler/ir_rewrite.hpp"
#include "compiler/pass_pipeline.hpp"

namespace wg {

namespace {
void appendOperandKey(std::string& key, const Operand& operand) {
  switch (operand.kind) {
    case Operand::Kind::Node:
      key += 'n' + std::to_string(operand.node) + '.' + std::to_string(operand.output);
      break;
    case Operand::Kind::Texture:
      key += 't' + std::to_string(operand.texture);
      break;
    case Operand::Kind::Constant:
      key += 'c' + std::to_string(static_cast<int>(operand.constant.type));
      for (int i = 0; i < operand.constant.width(); ++i)
        key += ':' + std::to_string(std::bit_cast<std::uint32_t>(operand.constant.v[i]));
      break;
  }
  key += ',';
}
}  // namespace

void eliminateCommonSubexpressions(IrGraph& graph) {
  std::vector<std::uint32_t> canonical(graph.nodes.size());
  std::unordered_map<std::string, std::uint32_t> seen;
  std::string key;
  for (std::uint32_t i = 0; i < graph.nodes.size(); ++i) {
    IrNode& node = graph.nodes[i];
    for (auto& operand : node.inputs)
      if (operand.kind == Operand::Kind::Node) operand.node = canonical[operand.node];
    key.assign(node.op->name);
    key += '|' + node.text + '|' + std::to_string(node.parameter) + '|' + std::to_string(static_cast<int>(node.valueType)) + '|';
    for (const auto& operand : node.inputs) appendOperandKey(key, operand);
    auto [it, inserted] = seen.emplace(key, i);
    // A weather node may reuse an unguarded one (computed anyway), never the reverse:
    // the weather nodes only run inside the weather branch.
    if (!inserted && graph.nodes[it->second].weather && !node.weather) it->second = i;
    canonical[i] = it->second;
  }
  graph.forEachRoot([&](Operand& operand) {
    if (operand.kind == Operand::Kind::Node) operand.node = canonical[operand.node];
  });
  // The merged duplicates are now unreferenced; dead-node-elim removes them.
}

}  // namespace wg
