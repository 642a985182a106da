// The statements of each surface function around the node body: written once, in
// GLSL, and printed by each syntax in its language (ShaderSyntax::frameCode).
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "backends/shader_syntax.hpp"

namespace wg {

// A surface function's statements around its body: geometry from the host's input
// struct wg_in before it; after it, (vertex) the varyings or (fragment) wg_N, the
// shading normal. The varyings keep their v_ names here; the surface writer renames
// them to the structs' fields. No camera transform, no lighting.
struct SurfaceFrameCode {
  std::string before, after;
};
SurfaceFrameCode surfaceFrameCode(const StageSource& source, const ShaderSyntax& syntax);
const std::vector<std::string_view>& surfaceFrameLibraryCalls(ShaderStage stage);

}  // namespace wg
