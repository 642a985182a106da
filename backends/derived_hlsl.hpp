// The HLSL of every op template and shader library, derived once from its GLSL
// (backends/glsl_to_hlsl.hpp) the first time a stage needs it.
#pragma once
#include <string_view>

#include "backends/glsl_to_hlsl.hpp"
#include "nodes/op_definition.hpp"

namespace wg {

// The frame block's matrices, which GLSL multiplies with '*' and HLSL with mul().
const HlslTranslation& frameMatrixTranslation();

std::string_view derivedHlsl(const ShaderLibrary& library);
std::string_view derivedHlsl(const OpDef& op);  // the op's hlsl override where it has one
bool derivedHlslCallsPrelude(const ShaderLibrary& library);  // callsHlslPrelude(derivedHlsl(library))

}  // namespace wg
