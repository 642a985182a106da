// Writes one stage of one material in one language: chooses the nodes the stage
// needs, names them through the identifier scope, fills each op's code template and
// hands the result to the language's syntax for the stage frame.
#pragma once
#include <string>
#include <vector>

#include "backends/shader_syntax.hpp"
#include "compiler/ir.hpp"
#include "compiler/material_interface.hpp"

namespace wg {

// Every node's temporary name, made once per material by the identifier function and
// shared by all four stages (names depend only on the node, never on the language).
std::vector<std::string> nameNodes(const IrGraph& graph, const MaterialInterface& interface);

std::string writeStage(const IrGraph& graph, const MaterialInterface& interface, const ShaderSyntax& syntax,
                       ShaderStage stage, std::string_view contentHash, const std::vector<std::string>& nodeNames);

}  // namespace wg
