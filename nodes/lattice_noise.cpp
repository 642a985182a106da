#include "nodes/lattice_noise.hpp"

#include <algorithm>
#include <cmath>

namespace wg {

namespace {
// Odd 32-bit multipliers from Hoskins' integer "hash without sine"; they decorrelate
// neighbouring cells well with two multiplies and one xor.
constexpr std::uint32_t kHashX = 1597334673u;
constexpr std::uint32_t kHashY = 3812015801u;
// PCG's LCG step, used to draw a second independent number from one hash.
constexpr std::uint32_t kLcgMultiplier = 747796405u;
constexpr std::uint32_t kLcgIncrement = 2891336453u;
// The top 24 bits convert to float exactly.
constexpr float kInv24Bit = 1.0f / 16777216.0f;

float toUnit(std::uint32_t n) { return static_cast<float>(n >> 8) * kInv24Bit; }
float quintic(float f) { return f * f * f * (f * (f * 6.f - 15.f) + 10.f); }
float mixf(float a, float b, float t) { return a + (b - a) * t; }
std::int32_t cellOf(float x) { return static_cast<std::int32_t>(std::floor(x)); }
}  // namespace

std::uint32_t latticeHash(std::int32_t x, std::int32_t y) {
  std::uint32_t qx = static_cast<std::uint32_t>(x) * kHashX;
  std::uint32_t qy = static_cast<std::uint32_t>(y) * kHashY;
  return (qx ^ qy) * kHashX;
}

float valueNoise(float x, float y) {
  float cx = std::floor(x), cy = std::floor(y);
  float fx = x - cx, fy = y - cy;
  float ux = quintic(fx), uy = quintic(fy);
  std::int32_t ix = cellOf(x), iy = cellOf(y);
  float a = toUnit(latticeHash(ix, iy));
  float b = toUnit(latticeHash(ix + 1, iy));
  float c = toUnit(latticeHash(ix, iy + 1));
  float d = toUnit(latticeHash(ix + 1, iy + 1));
  return mixf(mixf(a, b, ux), mixf(c, d, ux), uy);
}

namespace {
float gradientDot(std::int32_t ix, std::int32_t iy, float dx, float dy) {
  std::uint32_t n = latticeHash(ix, iy);
  float gx = toUnit(n) * 2.f - 1.f;
  float gy = toUnit(n * kLcgMultiplier + kLcgIncrement) * 2.f - 1.f;
  return gx * dx + gy * dy;
}
}  // namespace

float gradientNoise(float x, float y) {
  float cx = std::floor(x), cy = std::floor(y);
  float fx = x - cx, fy = y - cy;
  float ux = quintic(fx), uy = quintic(fy);
  std::int32_t ix = cellOf(x), iy = cellOf(y);
  float a = gradientDot(ix, iy, fx, fy);
  float b = gradientDot(ix + 1, iy, fx - 1.f, fy);
  float c = gradientDot(ix, iy + 1, fx, fy - 1.f);
  float d = gradientDot(ix + 1, iy + 1, fx - 1.f, fy - 1.f);
  return std::clamp(0.5f + 0.5f * mixf(mixf(a, b, ux), mixf(c, d, ux), uy), 0.f, 1.f);
}

const ShaderLibrary kLatticeNoiseLibrary = {
    "lattice_noise",
    R"(uint wg_lattice_hash(const ivec2 cell) {
  uvec2 q = uvec2(cell) * uvec2(1597334673u, 3812015801u);
  return (q.x ^ q.y) * 1597334673u;
}
float wg_hash_to_unit(const uint n) { return float(n >> 8u) * (1.0 / 16777216.0); }
vec2 wg_quintic(const vec2 f) { return f * f * f * (f * (f * 6.0 - 15.0) + 10.0); }
// The four corner hashes in one uvec4: the same per-corner arithmetic as
// wg_lattice_hash, in a quarter of the instructions.
vec4 wg_corner_values(const ivec2 i) {
  uvec4 x = uvec4(ivec4(i.x, i.x + 1, i.x, i.x + 1)) * 1597334673u;
  uvec4 y = uvec4(ivec4(i.y, i.y, i.y + 1, i.y + 1)) * 3812015801u;
  return vec4((x ^ y) * 1597334673u >> 8u) * (1.0 / 16777216.0);
}
float wg_value_noise(const vec2 p) {
  vec2 cell = floor(p);
  vec2 u = wg_quintic(p - cell);
  vec4 c = wg_corner_values(ivec2(cell));
  vec2 edge = mix(c.xz, c.yw, u.x);
  return mix(edge.x, edge.y, u.y);
}
float wg_gradient_dot(const ivec2 i, const vec2 d) {
  uint n = wg_lattice_hash(i);
  vec2 g = vec2(wg_hash_to_unit(n), wg_hash_to_unit(n * 747796405u + 2891336453u)) * 2.0 - 1.0;
  return g.x * d.x + g.y * d.y;
}
float wg_gradient_noise(const vec2 p) {
  vec2 cell = floor(p);
  vec2 f = p - cell;
  vec2 u = wg_quintic(f);
  ivec2 i = ivec2(cell);
  float a = wg_gradient_dot(i, f);
  float b = wg_gradient_dot(i + ivec2(1, 0), f - vec2(1.0, 0.0));
  float c = wg_gradient_dot(i + ivec2(0, 1), f - vec2(0.0, 1.0));
  float d = wg_gradient_dot(i + ivec2(1, 1), f - vec2(1.0, 1.0));
  return clamp(0.5 + 0.5 * mix(mix(a, b, u.x), mix(c, d, u.x), u.y), 0.0, 1.0);
}
)",
    {}};

}  // namespace wg
