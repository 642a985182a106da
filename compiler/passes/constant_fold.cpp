// Constant folding through each op's CPU semantics (MaterialX only elides constant
// nodes; we evaluate whole constant subgraphs). Results that are not finite stay
// unfolded so the shader keeps the original arithmetic.
#include <optional>

#include "compiler/ir_rewrite.hpp"
#include "compiler/pass_pipeline.hpp"

namespace wg {

void foldConstants(IrGraph& graph) {
  std::vector<std::optional<Value>> folded(graph.nodes.size());
  auto substitute = [&](Operand& operand) {
    if (operand.kind != Operand::Kind::Node || !folded[operand.node]) return;
    const IrNode& source = graph.nodes[operand.node];
    operand = Operand::ofConstant(applyAccessor(*folded[operand.node], source.op->outputs[operand.output].accessor));
  };
  std::vector<Value> inputs;
  for (std::size_t i = 0; i < graph.nodes.size(); ++i) {
    IrNode& node = graph.nodes[i];
    for (auto& operand : node.inputs) substitute(operand);
    if (node.op->purity != OpPurity::Pure || !node.op->eval) continue;
    bool allConstant = true;
    inputs.clear();
    for (std::size_t p = 0; p < node.inputs.size(); ++p) {
      if (node.inputs[p].kind != Operand::Kind::Constant) {
        allConstant = false;
        break;
      }
      inputs.push_back(node.inputs[p].constant.convertedTo(node.inputTypes[p]));
    }
    if (!allConstant) continue;
    EvalContext context;
    context.text = node.text;
    Value result = node.op->eval(inputs.data(), context);
    if (result.allFinite()) folded[i] = result;
  }
  graph.forEachRoot(substitute);
}

}  // namespace wg
