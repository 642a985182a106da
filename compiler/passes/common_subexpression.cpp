// Common-subexpression elimination: nodes with the same op, settings and operands
// (after earlier merges) are one node. Graph content, not spelling, decides.
#include <bit>
#include <unordered_map>

#include "compiler/content_hash.hpp"
#include "compiler/ir_rewrite.hpp"
#include "compiler/pass_pipeline.hpp"

namespace wg {

namespace {

// Constants compare by bit pattern: 0.0 and -0.0 differ, NaN equals itself.
bool sameBits(const Value& a, const Value& b) {
  if (a.type != b.type) return false;
  for (int i = 0; i < a.width(); ++i)
    if (std::bit_cast<std::uint32_t>(a.v[i]) != std::bit_cast<std::uint32_t>(b.v[i])) return false;
  return true;
}

bool sameOperand(const Operand& a, const Operand& b) {
  if (a.kind != b.kind) return false;
  switch (a.kind) {
    case Operand::Kind::Node: return a.node == b.node && a.output == b.output;
    case Operand::Kind::Texture: return a.texture == b.texture;
    case Operand::Kind::Constant: return sameBits(a.constant, b.constant);
  }
  return false;
}

struct NodeKey {
  const IrNode* node;
};

struct NodeKeyHash {
  std::size_t operator()(const NodeKey& k) const {
    StableHasher h;
    h.add(k.node->op->name);
    h.add(k.node->text);
    h.add(static_cast<std::uint64_t>(k.node->parameter + 1) << 8 | static_cast<std::uint64_t>(k.node->valueType));
    for (const auto& o : k.node->inputs) {
      h.add(static_cast<std::uint64_t>(o.kind));
      if (o.kind == Operand::Kind::Node) h.add(std::uint64_t(o.node) << 8 | o.output);
      else if (o.kind == Operand::Kind::Texture) h.add(static_cast<std::uint64_t>(o.texture));
      else
        for (int i = 0; i < o.constant.width(); ++i) h.add(std::bit_cast<std::uint32_t>(o.constant.v[i]));
    }
    return static_cast<std::size_t>(h.value());
  }
};

struct NodeKeyEqual {
  bool operator()(const NodeKey& a, const NodeKey& b) const {
    const IrNode& x = *a.node;
    const IrNode& y = *b.node;
    if (x.op != y.op || x.text != y.text || x.parameter != y.parameter || x.valueType != y.valueType ||
        x.inputs.size() != y.inputs.size())
      return false;
    for (std::size_t i = 0; i < x.inputs.size(); ++i)
      if (!sameOperand(x.inputs[i], y.inputs[i])) return false;
    return true;
  }
};

}  // namespace

void eliminateCommonSubexpressions(IrGraph& graph) {
  std::vector<std::uint32_t> canonical(graph.nodes.size());
  std::unordered_map<NodeKey, std::uint32_t, NodeKeyHash, NodeKeyEqual> seen;
  seen.reserve(graph.nodes.size());
  for (std::uint32_t i = 0; i < graph.nodes.size(); ++i) {
    IrNode& node = graph.nodes[i];
    for (auto& operand : node.inputs)
      if (operand.kind == Operand::Kind::Node) operand.node = canonical[operand.node];
    auto [it, inserted] = seen.emplace(NodeKey{&node}, i);
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
