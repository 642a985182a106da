// How many distinct constants a material's shaders hold. glslang looks every new
// constant up linearly among those of its type, so compile time grows with the square
// of this count: 5,000 distinct scalars compile in under a second, 20,000 take 8 s and
// a 100,000-node graph of them over two minutes (docs/BENCHMARKS.md). Node counts alone
// stay linear, so the limit is on constants.
#pragma once
#include <cstddef>

#include "compiler/ir.hpp"

namespace wg {

inline constexpr std::size_t kMaxDistinctConstants = 8192;

// Distinct scalar values (each vector component counted, by bit pattern) plus distinct
// vector constants, over every constant operand of the IR: what glslang will create.
std::size_t distinctConstantCount(const IrGraph& ir);

}  // namespace wg
