// GLSL of the snow puffs: the particle step (compute) and the soft billboards
// (vertex and fragment). Compiled and reflected like every runtime shader.
#pragma once
#include <string_view>

namespace wg::snow {

std::string_view puffSimulateSource();
std::string_view puffVertexSource();
std::string_view puffFragmentSource();

}  // namespace wg::snow
