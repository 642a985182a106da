// GLSL 450 of the deformation pass (issue 5, §2): stamps, normals over touched
// rectangles, and the global refill. Compiled at start-up through the project's
// glslang wrapper; the descriptor layout comes from their SPIRV-Cross reflection.
#pragma once
#include <string>
#include <string_view>

namespace wg::snow {

std::string_view stampShaderSource();
std::string_view normalShaderSource();
std::string_view refillShaderSource();

}  // namespace wg::snow
