// Writes one stage of one material in one language: chooses the nodes the stage
// needs, names them through the identifier scope, fills each op's code template and
// hands the result to the language's syntax for the stage frame.
#pragma once
#include <string>

#include "backends/shader_syntax.hpp"
#include "compiler/ir.hpp"
#include "compiler/material_interface.hpp"

namespace wg {

std::string writeStage(const IrGraph& graph, const MaterialInterface& interface, const ShaderSyntax& syntax,
                       ShaderStage stage, std::string_view contentHash);

}  // namespace wg
