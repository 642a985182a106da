// Common-subexpression elimination: nodes with the same op, settings and operands
// (after earlier merges) are one node. Graph content, not spelling, decides.
#include <bit>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

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

// A hash of what sameNode compares, mixed a word at a time (multiply and rotate): it
// only spreads nodes over the table, so unlike the content hash it need not be stable.
std::uint64_t mix(std::uint64_t h, std::uint64_t word) { return std::rotl((h ^ word) * 0x9E3779B97F4A7C15ull, 29); }

std::uint64_t nodeHash(const IrNode& node) {
  std::uint64_t h = mix(reinterpret_cast<std::uintptr_t>(node.op), std::hash<std::string>{}(node.text));
  h = mix(h, static_cast<std::uint64_t>(node.parameter + 1) << 8 | static_cast<std::uint64_t>(node.valueType));
  for (const auto& o : node.inputs) {
    h = mix(h, static_cast<std::uint64_t>(o.kind));
    if (o.kind == Operand::Kind::Node) h = mix(h, std::uint64_t(o.node) << 8 | o.output);
    else if (o.kind == Operand::Kind::Texture) h = mix(h, static_cast<std::uint64_t>(o.texture));
    else
      for (int i = 0; i < o.constant.width(); ++i) h = mix(h, std::bit_cast<std::uint32_t>(o.constant.v[i]));
  }
  return h;
}

bool sameNode(const IrNode& x, const IrNode& y) {
  if (x.op != y.op || x.text != y.text || x.parameter != y.parameter || x.valueType != y.valueType ||
      x.inputs.size() != y.inputs.size())
    return false;
  for (std::size_t i = 0; i < x.inputs.size(); ++i)
    if (!sameOperand(x.inputs[i], y.inputs[i])) return false;
  return true;
}

// The first node equal to each node, in one open-addressed table of node indices
// (linear probing, at most half full): no allocation per node.
class NodeTable {
 public:
  explicit NodeTable(std::size_t nodes) : slots_(std::bit_ceil(2 * nodes + 2), kEmpty), mask_(slots_.size() - 1) {}
  // The index of the node equal to graph.nodes[i] already in the table, or i, added.
  std::uint32_t& findOrAdd(const std::vector<IrNode>& nodes, std::uint32_t i) {
    for (std::size_t at = nodeHash(nodes[i]) & mask_;; at = (at + 1) & mask_) {
      if (slots_[at] == kEmpty) return slots_[at] = i;
      if (sameNode(nodes[slots_[at]], nodes[i])) return slots_[at];
    }
  }

 private:
  static constexpr std::uint32_t kEmpty = ~std::uint32_t{0};
  std::vector<std::uint32_t> slots_;
  std::size_t mask_;
};

}  // namespace

void eliminateCommonSubexpressions(IrGraph& graph) {
  std::vector<std::uint32_t> canonical(graph.nodes.size());
  NodeTable seen(graph.nodes.size());
  for (std::uint32_t i = 0; i < graph.nodes.size(); ++i) {
    IrNode& node = graph.nodes[i];
    for (auto& operand : node.inputs)
      if (operand.kind == Operand::Kind::Node) operand.node = canonical[operand.node];
    std::uint32_t& first = seen.findOrAdd(graph.nodes, i);
    // A weather node may reuse an unguarded one (computed anyway), never the reverse:
    // the weather nodes only run inside the weather branch.
    if (graph.nodes[first].weather && !node.weather) first = i;
    canonical[i] = first;
  }
  graph.forEachRoot([&](Operand& operand) {
    if (operand.kind == Operand::Kind::Node) operand.node = canonical[operand.node];
  });
  // The merged duplicates are now unreferenced; dead-node-elim removes them.
}

}  // namespace wg
