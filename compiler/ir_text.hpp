// The IR as text, for people debugging the passes (weathergen compile --dump-ir-after).
// Deterministic and name-independent: nodes are n<index>, parameters p<index>,
// textures t<index>; node ids never appear. Parameter and texture names, which are
// part of the material's interface, appear escaped (quoteUserText).
#pragma once
#include <string>

#include "compiler/ir.hpp"

namespace wg {

// "parameters:", "textures:", "nodes:" and "outputs:" sections, one item a line:
//   n3 vec3 = multiply(a: n1, b: (0.5, 0.4, 0.3)) [weather]
std::string formatIrText(const IrGraph& graph);

}  // namespace wg
