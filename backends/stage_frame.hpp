// The statements of each stage's main() around the node body: written once, in GLSL,
// and printed by each syntax in its language (ShaderSyntax::frameCode). Each language
// adds only its entry point's signature and its way of returning the results.
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "backends/shader_syntax.hpp"

namespace wg {

// World-space geometry, the body, the offset and the varyings, then the clip position.
void appendVertexMain(std::string& out, const StageSource& source, const ShaderSyntax& syntax);
// Geometry from the varyings, the body, alpha test, shading, alpha and debug views;
// leaves wg_color and wg_alpha for the language to write out.
void appendFragmentMain(std::string& out, const StageSource& source, const ShaderSyntax& syntax);
// The library functions the stage's frame calls (its texts are fixed: found once).
const std::vector<std::string_view>& frameLibraryCalls(ShaderStage stage);

}  // namespace wg
