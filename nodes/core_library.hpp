// Shader functions every stage uses (robust normalisation of possibly-zero vectors).
#pragma once
#include "nodes/op_definition.hpp"

namespace wg {
extern const ShaderLibrary kCoreLibrary;
}
