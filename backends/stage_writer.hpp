// Writes the body of one stage of one material in one language: chooses the nodes the
// stage needs, names them, and fills each op's code template. The surface writer wraps
// the body in the surface's functions.
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "backends/shader_syntax.hpp"
#include "compiler/ir.hpp"
#include "compiler/material_interface.hpp"

namespace wg {

// Every node's temporary name, made once per material and shared by all four stages
// (names depend only on the node, never on the language).
std::vector<std::string> nameNodes(const IrGraph& graph);

// The stage's body, libraries and calls, before a frame (backends/stage_frame.hpp)
// wraps them.
StageSource writeStageSource(const IrGraph& graph, const MaterialInterface& interface, const ShaderSyntax& syntax,
                             ShaderStage stage, const std::vector<std::string>& nodeNames);

}  // namespace wg
