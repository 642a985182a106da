// Algebraic identities that constant folding cannot see because one input varies:
// lerp(a, a, t) = a, lerp(a, b, 0) = a, lerp(a, b, 1) = b, x * 1 = x, x + 0 = x,
// x - 0 = x, x / 1 = x. A node is replaced only by an operand of its own type, so no
// use changes meaning. (x * 0 is left alone: it is not 0 when x is NaN or infinite.)
#include <optional>

#include "compiler/ir_rewrite.hpp"
#include "compiler/pass_pipeline.hpp"

namespace wg {

namespace {

bool isConstant(const Operand& o, float x) {
  if (o.kind != Operand::Kind::Constant || o.constant.type == ValueType::Bool) return false;
  for (int i = 0; i < o.constant.width(); ++i)
    if (o.constant.v[i] != x) return false;
  return true;
}

bool sameOperand(const Operand& a, const Operand& b) {
  if (a.kind != b.kind) return false;
  if (a.kind == Operand::Kind::Node) return a.node == b.node && a.output == b.output;
  if (a.kind == Operand::Kind::Constant) return a.constant.type == b.constant.type && a.constant == b.constant;
  return false;
}

// The operand the node reduces to, if an identity applies.
std::optional<Operand> identity(const IrNode& node) {
  std::string_view op = node.op->name;
  const auto& in = node.inputs;
  if (op == "lerp") {
    if (sameOperand(in[0], in[1]) || isConstant(in[2], 0.f)) return in[0];
    if (isConstant(in[2], 1.f)) return in[1];
  } else if (op == "multiply") {
    if (isConstant(in[1], 1.f)) return in[0];
    if (isConstant(in[0], 1.f)) return in[1];
  } else if (op == "add") {
    if (isConstant(in[1], 0.f)) return in[0];
    if (isConstant(in[0], 0.f)) return in[1];
  } else if (op == "subtract") {
    if (isConstant(in[1], 0.f)) return in[0];
  } else if (op == "divide") {
    if (isConstant(in[1], 1.f)) return in[0];
  }
  return std::nullopt;
}

}  // namespace

void simplifyAlgebra(IrGraph& graph) {
  std::vector<std::optional<Operand>> replaced(graph.nodes.size());
  auto substitute = [&](Operand& operand) {
    if (operand.kind == Operand::Kind::Node && operand.output == 0 && replaced[operand.node] &&
        graph.nodes[operand.node].op->outputs[0].accessor.empty())
      operand = *replaced[operand.node];
  };
  for (std::size_t i = 0; i < graph.nodes.size(); ++i) {
    IrNode& node = graph.nodes[i];
    for (auto& operand : node.inputs) substitute(operand);
    auto result = identity(node);
    if (!result) continue;
    if (result->kind == Operand::Kind::Constant) {
      replaced[i] = Operand::ofConstant(result->constant.convertedTo(node.valueType));
    } else if (result->type == node.valueType) {
      replaced[i] = *result;  // a narrower operand would change the users' types: keep the node
    }
  }
  graph.forEachRoot(substitute);
}

}  // namespace wg
