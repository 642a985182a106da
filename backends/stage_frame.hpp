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

// A surface function's statements (--target surface): geometry from the host's input
// struct wg_in, the body, then (vertex) the varyings or (fragment) wg_N, the shading
// normal. The varyings keep their v_ names here; the surface writer renames them to
// the structs' fields. No camera transform, no lighting.
void appendSurfaceVertexBody(std::string& out, const StageSource& source, const ShaderSyntax& syntax);
void appendSurfaceFragmentBody(std::string& out, const StageSource& source, const ShaderSyntax& syntax);
const std::vector<std::string_view>& surfaceFrameLibraryCalls(ShaderStage stage);

}  // namespace wg
