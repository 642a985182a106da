#include "compiler/ir_verifier.hpp"

#include "compiler/pass_pipeline.hpp"

namespace wg {

namespace {

std::string nodeLabel(std::size_t index, const IrNode& node) {
  return "node " + std::to_string(index) + " (" + std::string(node.op ? node.op->name : "no op") + ")";
}

std::string operandLabel(std::size_t index, const IrNode& node, std::size_t port) {
  return nodeLabel(index, node) + " input '" + std::string(node.op->inputs[port].name) + "'";
}

// What an operand refers to exists and delivers the type it claims. `before` bounds
// node references: the referring node's index, or the node count for a root.
std::string checkOperandSource(const IrGraph& graph, const Operand& operand, std::size_t before) {
  switch (operand.kind) {
    case Operand::Kind::Node: {
      if (operand.node >= before)
        return "refers to node " + std::to_string(operand.node) +
               (operand.node < graph.nodes.size() ? ", which is not before it (a cycle or a broken order)"
                                                  : ", which does not exist");
      const IrNode& source = graph.nodes[operand.node];
      if (!source.op || operand.output >= source.op->outputs.size())
        return "reads output " + std::to_string(operand.output) + " of node " + std::to_string(operand.node) +
               ", which it does not have";
      if (operand.type != source.outputType(operand.output))
        return "claims " + std::string(typeName(operand.type)) + " but node " + std::to_string(operand.node) +
               " delivers " + std::string(typeName(source.outputType(operand.output)));
      return "";
    }
    case Operand::Kind::Texture:
      if (operand.texture < 0 || static_cast<std::size_t>(operand.texture) >= graph.textures.size())
        return "names texture " + std::to_string(operand.texture) + ", which is not declared";
      return operand.type == ValueType::Texture ? "" : "is a texture but claims another type";
    case Operand::Kind::Constant:
      if (operand.type != operand.constant.type)
        return "claims " + std::string(typeName(operand.type)) + " but holds a " +
               std::string(typeName(operand.constant.type)) + " constant";
      return "";
  }
  return "has an unknown kind";
}

// Port types follow the signature; every generic port shares one float vector type.
std::string checkPortTypes(std::size_t index, const IrNode& node, std::optional<ValueType>& generic) {
  for (std::size_t port = 0; port < node.op->inputs.size(); ++port) {
    ValueType actual = node.inputTypes[port];
    if (auto fixed = signatureValueType(node.op->inputs[port].type)) {
      if (actual != *fixed)
        return operandLabel(index, node, port) + " is typed " + std::string(typeName(actual)) + ", its signature says " +
               std::string(typeName(*fixed));
      continue;
    }
    if (!isFloatVector(actual) || (generic && actual != *generic))
      return operandLabel(index, node, port) + " is a generic port typed " + std::string(typeName(actual)) +
             (generic ? ", another generic port is " + std::string(typeName(*generic)) : "");
    generic = actual;
  }
  return "";
}

std::string checkValueType(const IrGraph& graph, std::size_t index, const IrNode& node, std::optional<ValueType> generic) {
  const bool isParameterOp = node.op->valueRule == ValueRule::Parameter;
  if (isParameterOp != (node.parameter >= 0))
    return nodeLabel(index, node) + (isParameterOp ? " names no parameter" : " names a parameter it does not read");
  std::optional<ValueType> expected;
  switch (node.op->valueRule) {
    case ValueRule::Fixed: expected = node.op->valueType; break;
    case ValueRule::Generic: expected = generic.value_or(ValueType::Float); break;
    case ValueRule::Parameter:
      if (static_cast<std::size_t>(node.parameter) >= graph.parameters.size())
        return nodeLabel(index, node) + " names parameter " + std::to_string(node.parameter) + ", which is not declared";
      expected = graph.parameters[static_cast<std::size_t>(node.parameter)].type;
      break;
    case ValueRule::SwizzleText:
      if (node.text.empty() || node.text.size() > 4) return nodeLabel(index, node) + " swizzles no channels or too many";
      expected = floatVectorOfWidth(static_cast<int>(node.text.size()));
      break;
  }
  if (expected && node.valueType != *expected)
    return nodeLabel(index, node) + " has value type " + std::string(typeName(node.valueType)) + ", its op's rule gives " +
           std::string(typeName(*expected));
  return "";
}

std::string checkNode(const IrGraph& graph, std::size_t index) {
  const IrNode& node = graph.nodes[index];
  if (!node.op) return nodeLabel(index, node) + " has no op";
  if (node.inputs.size() != node.op->inputs.size() || node.inputTypes.size() != node.op->inputs.size())
    return nodeLabel(index, node) + " has " + std::to_string(node.inputs.size()) + " operands and " +
           std::to_string(node.inputTypes.size()) + " port types for " + std::to_string(node.op->inputs.size()) + " ports";
  for (std::size_t port = 0; port < node.inputs.size(); ++port) {
    const Operand& operand = node.inputs[port];
    if (std::string problem = checkOperandSource(graph, operand, index); !problem.empty())
      return operandLabel(index, node, port) + " " + problem;
    if ((operand.kind == Operand::Kind::Texture) != (node.op->inputs[port].type == PortType::TextureName))
      return operandLabel(index, node, port) + " mixes up a texture and a value";
    if (!isImplicitlyConvertible(operand.type, node.inputTypes[port]))
      return operandLabel(index, node, port) + " gets " + std::string(typeName(operand.type)) + " for a " +
             std::string(typeName(node.inputTypes[port])) + " port";
  }
  std::optional<ValueType> generic;
  if (std::string problem = checkPortTypes(index, node, generic); !problem.empty()) return problem;
  return checkValueType(graph, index, node, generic);
}

// Output bindings: the PBR fields, then the coverage terms (floats).
std::string checkRoots(const IrGraph& graph, const std::array<Operand, kIrOutputCount>& roots, std::string_view what) {
  for (std::size_t i = 0; i < roots.size(); ++i) {
    bool pbr = i < kPbrFieldCount;
    std::string_view name = pbr ? pbrFields()[i].name : coverageTerms()[i - kPbrFieldCount].name;
    ValueType fieldType = pbr ? pbrFields()[i].type : ValueType::Float;
    std::string label = std::string(what) + " '" + std::string(name) + "'";
    if (std::string problem = checkOperandSource(graph, roots[i], graph.nodes.size()); !problem.empty())
      return label + " " + problem;
    if (roots[i].kind == Operand::Kind::Texture || !isImplicitlyConvertible(roots[i].type, fieldType))
      return label + " is bound to a " + std::string(typeName(roots[i].type)) + " value, the field is " +
             std::string(typeName(fieldType));
  }
  return "";
}

// Interpolants: vertex-rate nodes, each named once, in index order.
std::string checkInterpolants(const IrGraph& graph) {
  for (std::size_t k = 0; k < graph.interpolants.size(); ++k) {
    std::uint32_t node = graph.interpolants[k];
    std::string label = "interpolant " + std::to_string(k) + " (node " + std::to_string(node) + ")";
    if (node >= graph.nodes.size()) return label + " does not exist";
    if (k > 0 && node <= graph.interpolants[k - 1]) return label + " is out of index order";
    if (graph.nodes[node].op->rate != OpRate::Vertex) return label + " is not a vertex-rate op";
  }
  return "";
}

std::string checkCanonicalOrder(const IrGraph& graph) {
  std::vector<std::uint32_t> order = canonicalNodeOrder(graph);
  if (order.size() != graph.nodes.size())
    return std::to_string(graph.nodes.size() - order.size()) + " node(s) are unreachable after the nodes were ordered";
  for (std::uint32_t i = 0; i < order.size(); ++i)
    if (order[i] != i)
      return "node " + std::to_string(i) + " is out of canonical order (node " + std::to_string(order[i]) + " belongs there)";
  return "";
}

}  // namespace

std::string verifyIr(const IrGraph& graph, const IrVerifyOptions& options) {
  for (std::size_t i = 0; i < graph.nodes.size(); ++i)
    if (std::string problem = checkNode(graph, i); !problem.empty()) return problem;
  if (std::string problem = checkRoots(graph, graph.outputs, "output"); !problem.empty()) return problem;
  if (graph.weatherGuarded())
    if (std::string problem = checkRoots(graph, graph.unweathered, "unweathered output"); !problem.empty()) return problem;
  if (std::string problem = checkInterpolants(graph); !problem.empty()) return problem;
  return options.canonicalOrder ? checkCanonicalOrder(graph) : "";
}

}  // namespace wg
