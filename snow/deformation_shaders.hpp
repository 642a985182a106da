// GLSL 4.40 of the deformation pass: stamps, normals over touched rectangles, the
// refill of printed tiles, recentring's tile transfers, and the mesh interactors' depth-from-below raster. Compiled at start-up through the project's
// glslang wrapper; the descriptor layout comes from their SPIRV-Cross reflection.
#pragma once
#include <string>
#include <string_view>

namespace wg::snow {

std::string_view stampShaderSource();
std::string_view normalShaderSource();
std::string_view refillShaderSource();
// Whole tiles from the map to its host copy, and back (recentring).
std::string_view tilesOutShaderSource();
std::string_view tilesInShaderSource();
std::string_view meshVertexShaderSource();
std::string_view meshFragmentShaderSource();

}  // namespace wg::snow
