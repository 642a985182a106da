// GLSL of the precipitation near the viewer (host/precipitation_pass.hpp): every
// particle derived on the GPU from its instance index and the time, no particle buffer.
// Compiled and reflected like every runtime shader.
#pragma once
#include <string_view>

namespace wg {

std::string_view precipitationVertexSource();
std::string_view precipitationFragmentSource();

}  // namespace wg
