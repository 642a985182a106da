// Deterministic 2D value and gradient noise, defined once for the CPU and, as shader
// library text, for GLSL and HLSL. Integer hashing of lattice cells makes the three
// agree to float rounding (no sin-based hashes, whose precision differs per GPU).
#pragma once
#include <cstdint>

#include "nodes/op_definition.hpp"

namespace wg {

std::uint32_t latticeHash(std::int32_t x, std::int32_t y);
float valueNoise(float x, float y);     // in [0, 1]
float gradientNoise(float x, float y);  // in [0, 1], 0.5 on lattice points

extern const ShaderLibrary kLatticeNoiseLibrary;

}  // namespace wg
