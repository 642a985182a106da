#include "compiler/ir_text.hpp"

#include <algorithm>

#include "compiler/literal.hpp"

namespace wg {

namespace {

std::string valueText(const Value& value) {
  if (value.type == ValueType::Bool) return value.asBool() ? "true" : "false";
  if (value.width() == 1) return formatFloat(value.x());
  std::string out = "(";
  for (int i = 0; i < value.width(); ++i) out += (i ? ", " : "") + formatFloat(value.v[static_cast<std::size_t>(i)]);
  return out + ")";
}

std::string operandText(const IrGraph& graph, const Operand& operand) {
  switch (operand.kind) {
    case Operand::Kind::Node: {
      std::string out = "n" + std::to_string(operand.node);
      const IrNode& source = graph.nodes[operand.node];
      if (source.op->outputs.size() > 1) out += "." + std::string(source.op->outputs[operand.output].name);
      return out;
    }
    case Operand::Kind::Texture: return "t" + std::to_string(operand.texture);
    case Operand::Kind::Constant: return valueText(operand.constant);
  }
  return "?";
}

std::string nodeText(const IrGraph& graph, std::size_t index) {
  const IrNode& node = graph.nodes[index];
  std::string out = "  n" + std::to_string(index) + " " + std::string(typeName(node.valueType)) + " = " +
                    std::string(node.op->name) + "(";
  if (node.parameter >= 0) out += "p" + std::to_string(node.parameter);
  for (std::size_t port = 0; port < node.inputs.size(); ++port) {
    const PortSpec& spec = node.op->inputs[port];
    out += (port ? ", " : "") + std::string(spec.name) + ": ";
    out += spec.type == PortType::Text ? "'" + quoteUserText(node.text) + "'" : operandText(graph, node.inputs[port]);
  }
  bool perVertex = std::find(graph.interpolants.begin(), graph.interpolants.end(), index) != graph.interpolants.end();
  return out + ")" + (node.weather ? " [weather]" : "") + (perVertex ? " [per vertex]" : "") + "\n";
}

std::string rootsText(const IrGraph& graph, const std::array<Operand, kIrOutputCount>& roots) {
  std::string out;
  for (std::size_t i = 0; i < roots.size(); ++i) {
    std::string_view name = i < kPbrFieldCount ? pbrFields()[i].name : coverageTerms()[i - kPbrFieldCount].name;
    out += "  " + std::string(name) + " = " + operandText(graph, roots[i]) + "\n";
  }
  return out;
}

}  // namespace

std::string formatIrText(const IrGraph& graph) {
  std::string out = "parameters:\n";
  for (std::size_t i = 0; i < graph.parameters.size(); ++i) {
    const ParameterDecl& p = graph.parameters[i];
    out += "  p" + std::to_string(i) + " " + std::string(typeName(p.type)) + " '" + quoteUserText(p.name) +
           "' = " + valueText(p.defaultValue) + "\n";
  }
  out += "textures:\n";
  for (std::size_t i = 0; i < graph.textures.size(); ++i)
    out += "  t" + std::to_string(i) + " '" + quoteUserText(graph.textures[i].name) + "'\n";
  out += "nodes:\n";
  for (std::size_t i = 0; i < graph.nodes.size(); ++i) out += nodeText(graph, i);
  out += "outputs:\n" + rootsText(graph, graph.outputs);
  if (graph.weatherGuarded()) out += "outputs without weather:\n" + rootsText(graph, graph.unweathered);
  return out;
}

}  // namespace wg
