// HLSL derived from GLSL, MaterialX style: shader code is written once, in GLSL, and
// the HLSL backend maps it token by token. Identifiers are renamed from a table
// (vec3 -> float3, mix -> lerp, fract -> frac, inversesqrt -> rsqrt, dFdx -> ddx, ...);
// a few calls are rewritten whole where HLSL spells them differently (one-argument
// vector constructors become casts, lessThan(a, b) becomes (a < b), texture sampling
// becomes a method call, a matrix times a vector becomes mul()). Comments, numbers,
// swizzles and members (anything after '.') are copied unchanged. GLSL whose meaning
// no token maps (mod's sign) calls helpers that hlslPrelude() defines.
#pragma once
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace wg {

struct HlslTranslation {
  // Names that hold matrices: "M * v" becomes "mul(M, v)" (a matrix is always on the left).
  std::vector<std::string_view> matrices;
  // Names this text alone spells differently (stage IO: v_color -> wg_in.v_color).
  std::vector<std::pair<std::string_view, std::string_view>> renames;
};

// Throws std::invalid_argument for GLSL it cannot map (a sampler2D outside texture()).
std::string glslToHlsl(std::string_view glsl, const HlslTranslation& translation = {});

// Helpers the translated code may call (each named "wg_glsl_*"); a stage emits them
// once, before the libraries, when its code calls one.
std::string_view hlslPrelude();
bool callsHlslPrelude(std::string_view hlsl);

}  // namespace wg
