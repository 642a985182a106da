// The statements of each stage's main() around the node body: written once, in GLSL,
// and printed by each syntax in its language (ShaderSyntax::frameCode). Each language
// adds only its entry point's signature and its way of returning the results.
#pragma once
#include <string>

#include "backends/shader_syntax.hpp"

namespace wg {

// Both return where in out the body starts, so the frame's own calls can be told
// from the body's (whose the stage writer already knows).
// World-space geometry, the body, the offset and the varyings, then the clip position.
std::size_t appendVertexMain(std::string& out, const StageSource& source, const ShaderSyntax& syntax);
// Geometry from the varyings, the body, alpha test, shading, alpha and debug views;
// leaves wg_color and wg_alpha for the language to write out.
std::size_t appendFragmentMain(std::string& out, const StageSource& source, const ShaderSyntax& syntax);

}  // namespace wg
