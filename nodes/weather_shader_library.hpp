// The weather functions as GLSL and HLSL library code.
#pragma once
#include "nodes/op_definition.hpp"

namespace wg {
extern const ShaderLibrary kWeatherLibrary;
}
