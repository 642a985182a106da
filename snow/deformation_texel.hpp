// One texel of the deformation height map, packed in 32 bits so a compute shader can
// merge overlapping stamps with a single atomicMax, in any order:
//   bits 31..16  print depth below the undisturbed snow surface, in kDepthQuantum steps
//   bits 15..0   rim height above it, in the same steps
// Deeper prints win (max of the high half); among untouched texels the highest rim
// wins (max of the low half, taken only when both depths are 0). A texel with any
// depth is a print, and its rim bits no longer matter: the snow there was packed down.
// The GLSL in stamp_shaders.cpp decodes the same way.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>

namespace wg::snow {

// 0.1 mm: far below a texel's 4 cm and below what a frame can show, and 16 bits of it
// still span 6.5 m of snow.
inline constexpr float kDepthQuantum = 1e-4f;
inline constexpr std::uint32_t kMaxQuanta = 0xFFFFu;
inline constexpr std::uint32_t kDepthShift = 16;

constexpr std::uint32_t toQuanta(float metres) {
  if (!(metres > 0.f)) return 0;
  float q = metres / kDepthQuantum + 0.5f;
  return q >= float(kMaxQuanta) ? kMaxQuanta : static_cast<std::uint32_t>(q);
}

constexpr std::uint32_t packTexel(float depth, float rim) {
  return (toQuanta(depth) << kDepthShift) | toQuanta(rim);
}
constexpr float texelDepth(std::uint32_t texel) { return float(texel >> kDepthShift) * kDepthQuantum; }
constexpr float texelRim(std::uint32_t texel) { return float(texel & kMaxQuanta) * kDepthQuantum; }

// Height of the deformed surface relative to the undisturbed snow (metres, up +).
constexpr float texelHeight(std::uint32_t texel) {
  return (texel >> kDepthShift) != 0 ? -texelDepth(texel) : texelRim(texel);
}

// Lowers both halves by `quanta`, never below 0: refill by fresh snow and drift.
constexpr std::uint32_t refillTexel(std::uint32_t texel, std::uint32_t quanta) {
  std::uint32_t depth = texel >> kDepthShift, rim = texel & kMaxQuanta;
  depth = depth > quanta ? depth - quanta : 0;
  rim = rim > quanta ? rim - quanta : 0;
  return (depth << kDepthShift) | rim;
}

}  // namespace wg::snow
