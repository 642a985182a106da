// GLSL 450 of the deformation pass: stamps, normals over touched rectangles, the
// global refill, and the mesh interactors' depth-from-below raster. Compiled at start-up through the project's
// glslang wrapper; the descriptor layout comes from their SPIRV-Cross reflection.
#pragma once
#include <string>
#include <string_view>

namespace wg::snow {

std::string_view stampShaderSource();
std::string_view normalShaderSource();
std::string_view refillShaderSource();
std::string_view meshVertexShaderSource();
std::string_view meshFragmentShaderSource();

}  // namespace wg::snow
