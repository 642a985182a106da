#include "snow/snow_stamp.hpp"

#include <algorithm>
#include <cmath>

#include "snow/deformation_texel.hpp"

namespace wg::snow {

namespace {
// Below this axis length the capsule is a disc (a body standing still).
constexpr float kDegenerateAxis = 1e-5f;
// The print wall slopes over this fraction of the smaller radius; a vertical wall would
// alias on the 4 cm grid.
constexpr float kWallFraction = 0.35f;
// A waisted stamp's arch, by t (0 at the heel centre, 1 at the toe centre): full over
// the middle tenth, gone a fifth of the way from either centre, so heel and ball each
// keep their full width and depth over two texels or more.
constexpr float kArchFlat = 0.05f, kArchReach = 0.3f;

float smoothstep(float e0, float e1, float x) {
  float t = std::clamp((x - e0) / (e1 - e0), 0.f, 1.f);
  return t * t * (3.f - 2.f * t);
}

// Signed distance to a 2D uneven capsule along +y from the origin (radius r1) to
// (0, h) (radius r2); negative inside. Exact where |r1 - r2| < h.
float unevenCapsuleDistance(glm::vec2 p, float r1, float r2, float h) {
  p.x = std::abs(p.x);
  if (h <= std::abs(r1 - r2)) return std::min(glm::length(p) - r1, glm::length(p - glm::vec2(0.f, h)) - r2);
  float b = (r1 - r2) / h, a = std::sqrt(1.f - b * b);
  float k = glm::dot(p, glm::vec2(-b, a));
  if (k < 0.f) return glm::length(p) - r1;
  if (k > a * h) return glm::length(p - glm::vec2(0.f, h)) - r2;
  return glm::dot(p, glm::vec2(a, b)) - r1;
}

float archWeight(float t) { return 1.f - smoothstep(kArchFlat, kArchReach, std::abs(t - 0.5f)); }
}  // namespace

StampProfile stampProfile(const Stamp& s, glm::vec2 point) {
  glm::vec2 axis = s.b - s.a;
  float h = glm::length(axis);
  glm::vec2 along = h > kDegenerateAxis ? axis / h : glm::vec2(0.f, 1.f);
  glm::vec2 across(along.y, -along.x);
  glm::vec2 d = point - s.a;
  glm::vec2 local(glm::dot(d, across), glm::dot(d, along));
  float distance = unevenCapsuleDistance(local, s.radiusA, s.radiusB, h);
  float t = h > kDegenerateAxis ? std::clamp(local.y / h, 0.f, 1.f) : 0.f;
  float arch = s.waist > 0.f ? archWeight(t) : 0.f;
  // The sides pulled in across the arch to about the waist (the capsule's half-width
  // there is about the radii's mix), and the print shallower there. The rim still
  // rings the capsule: a 4 cm map cannot hold a ridge inside the waist's hollow.
  float sole = distance + arch * std::max(s.radiusA + (s.radiusB - s.radiusA) * t - s.waist, 0.f);
  float depth = s.depthA + (s.depthB - s.depthA) * t;
  depth += (s.archDepth - depth) * arch;
  float wall = kWallFraction * std::min(s.radiusA, s.radiusB);
  StampProfile out;
  out.depth = depth * smoothstep(0.f, wall, -sole);
  if (distance > 0.f && distance < s.rimWidth) {
    float u = distance / s.rimWidth;
    out.rim = s.rimHeight * 4.f * u * (1.f - u);  // a parabolic ridge, 0 at both edges
  }
  return out;
}

TexelRect stampReach(const Stamp& s, const SnowWindow& window) {
  float reach = std::max(s.radiusA, s.radiusB) + s.rimWidth;
  glm::vec2 lo = glm::min(s.a, s.b) - reach, hi = glm::max(s.a, s.b) + reach;
  glm::ivec2 first = window.texelAt(lo), last = window.texelAt(hi);
  return TexelRect{first, last - first + 1};
}

TexelRect stampBounds(const Stamp& s, const SnowWindow& window) {
  return stampReach(s, window).intersect(window.rect());
}

std::uint32_t stampTexel(const Stamp& s, const SnowWindow& window, glm::ivec2 texel) {
  StampProfile p = stampProfile(s, window.texelCentre(texel));
  return packTexel(p.depth, p.rim);
}

float deepestPrint(const SnowCover& cover) {
  return std::max(cover.depth, 0.f) * (1.f - kFreshSnowDensity / kPackedSnowDensity);
}

Stamp footprint(glm::vec2 centre, glm::vec2 heading, const FootShape& foot, const SnowCover& cover, float sink) {
  glm::vec2 dir = glm::length(heading) > 0.f ? glm::normalize(heading) : glm::vec2(0.f, 1.f);
  float depth = std::min(sink, deepestPrint(cover));
  Stamp s;
  // Capsule centres sit one radius in from the heel and toe ends.
  s.a = centre - dir * (foot.length * 0.5f - foot.heelRadius);
  s.b = centre + dir * (foot.length * 0.5f - foot.toeRadius);
  s.radiusA = foot.heelRadius;
  s.radiusB = foot.toeRadius;
  s.depthA = depth;
  s.depthB = depth * foot.toeDepthFraction;
  s.rimWidth = foot.rimWidth;
  s.rimHeight = kRimHeightFraction * depth;
  s.waist = foot.waist;
  s.archDepth = depth * foot.archDepthFraction;
  return s;
}

Stamp capsule(glm::vec2 from, glm::vec2 to, float radius, const SnowCover& cover, float sink) {
  float depth = std::min(sink, deepestPrint(cover));
  Stamp s;
  s.a = from;
  s.b = to;
  s.radiusA = s.radiusB = radius;
  s.depthA = s.depthB = depth;
  s.rimWidth = kRimWidthFraction * radius;
  s.rimHeight = kRimHeightFraction * depth;
  return s;
}

}  // namespace wg::snow
