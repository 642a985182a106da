// Appends typed nodes to an IrGraph, for passes that synthesise subgraphs. Types are
// resolved as the IR builder resolves them (generic T = widest input, scalar splat).
#pragma once
#include <initializer_list>
#include <string_view>
#include <utility>

#include "compiler/ir.hpp"

namespace wg {

class IrNodeBuilder {
 public:
  // weatherNodes: mark every added node as weather (shaders run it only while weather
  // is active), as the weather-inject pass needs.
  IrNodeBuilder(IrGraph& graph, bool weatherNodes) : graph_(graph), weatherNodes_(weatherNodes) {}

  // A node of `op` with the given inputs; unspecified ports take their defaults.
  // Throws std::logic_error on a misuse (unknown op or port, missing required input):
  // passes build only fixed, tested shapes, so that is a weathergen bug.
  Operand add(std::string_view op, std::initializer_list<std::pair<std::string_view, Operand>> inputs);
  Operand parameter(int index);
  // Another output of a multi-output node ("y" of a split).
  Operand output(const Operand& node, std::string_view name) const;

  static Operand constant(float x) { return Operand::ofConstant(Value::scalar(x)); }
  static Operand constant(const Value& v) { return Operand::ofConstant(v); }

 private:
  IrGraph& graph_;
  bool weatherNodes_;
};

}  // namespace wg
