#include "compiler/ir_node_builder.hpp"

#include <algorithm>
#include <stdexcept>

#include "nodes/op_registry.hpp"

namespace wg {

namespace {
ValueType portValueType(PortType type, ValueType generic) { return signatureValueType(type).value_or(generic); }
}  // namespace

Operand IrNodeBuilder::add(std::string_view opName, std::initializer_list<std::pair<std::string_view, Operand>> inputs) {
  const OpDef* op = findOp(opName);
  if (!op) throw std::logic_error("IrNodeBuilder: unknown op " + std::string(opName));
  IrNode node;
  node.op = op;
  node.weather = weatherNodes_;
  node.inputs.reserve(op->inputs.size());
  node.inputTypes.reserve(op->inputs.size());
  int width = 1;
  std::size_t matched = 0;
  for (const auto& spec : op->inputs) {
    auto given = std::find_if(inputs.begin(), inputs.end(), [&](const auto& p) { return p.first == spec.name; });
    if (given != inputs.end()) {
      node.inputs.push_back(given->second);
      ++matched;
    } else if (spec.defaultValue) {
      node.inputs.push_back(Operand::ofConstant(*spec.defaultValue));
    } else {
      throw std::logic_error("IrNodeBuilder: " + std::string(opName) + " needs " + std::string(spec.name));
    }
    if (spec.type == PortType::Generic) width = std::max(width, componentCount(node.inputs.back().type));
  }
  // A given port no spec took is not the op's.
  if (matched != inputs.size())
    for (const auto& [port, operand] : inputs)
      if (!op->findInput(port)) throw std::logic_error("IrNodeBuilder: " + std::string(opName) + " has no port " + std::string(port));
  ValueType generic = floatVectorOfWidth(width);
  for (std::size_t i = 0; i < op->inputs.size(); ++i) {
    ValueType port = portValueType(op->inputs[i].type, generic);
    if (!isImplicitlyConvertible(node.inputs[i].type, port))
      throw std::logic_error("IrNodeBuilder: type mismatch at " + std::string(opName) + "." + std::string(op->inputs[i].name));
    node.inputTypes.push_back(port);
  }
  node.valueType = op->valueRule == ValueRule::Generic ? generic : op->valueType;
  graph_.nodes.push_back(std::move(node));
  auto index = static_cast<std::uint32_t>(graph_.nodes.size() - 1);
  return Operand::ofNode(index, 0, graph_.nodes.back().outputType(0));
}

Operand IrNodeBuilder::parameter(int index) {
  IrNode node;
  node.op = findOp("parameter");
  node.parameter = index;
  node.valueType = graph_.parameters[static_cast<std::size_t>(index)].type;
  node.weather = weatherNodes_;
  graph_.nodes.push_back(std::move(node));
  auto at = static_cast<std::uint32_t>(graph_.nodes.size() - 1);
  return Operand::ofNode(at, 0, graph_.nodes.back().valueType);
}

Operand IrNodeBuilder::output(const Operand& node, std::string_view name) const {
  const IrNode& n = graph_.nodes[node.node];
  int index = n.op->findOutput(name);
  if (index < 0) throw std::logic_error("IrNodeBuilder: no output " + std::string(name));
  return Operand::ofNode(node.node, static_cast<std::uint8_t>(index), n.outputType(static_cast<std::size_t>(index)));
}

}  // namespace wg
