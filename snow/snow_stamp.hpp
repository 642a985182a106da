// One deformation stamp: an uneven capsule in the ground plane, from centre `a` with
// radius and depth (radiusA, depthA) to centre `b` with (radiusB, depthB), and a raised
// rim just outside it. A footprint is a boot sole from heel (a) to ball and toe (b),
// aligned to the heading, waisted at the arch: narrower and shallower there than at the
// heel and toe (`waist`, `archDepth`; a waist of 0 is a plain capsule). A moving body or
// a wheel is a capsule from its previous to its current position, so nothing it passed
// over in one frame is skipped. The layout is std430 so the same records
// go to the compute shader.
#pragma once
#include <glm/glm.hpp>

#include <cstdint>

#include "snow/snow_window.hpp"

namespace wg::snow {

struct Stamp {
  glm::vec2 a{0.f}, b{0.f};  // world xz, metres
  float radiusA = 0.f, radiusB = 0.f;
  float depthA = 0.f, depthB = 0.f;  // already limited by the local snow depth
  float rimWidth = 0.f, rimHeight = 0.f;
  float waist = 0.f;      // half the sole's width at the arch; 0: no waist
  float archDepth = 0.f;  // the print's depth at the arch, where the weight rests least
};
static_assert(sizeof(Stamp) == 12 * sizeof(float), "Stamp is mirrored by the GLSL struct");

// Depth below and rim above the undisturbed surface that a stamp leaves at a point.
struct StampProfile {
  float depth = 0.f, rim = 0.f;
};
StampProfile stampProfile(const Stamp& stamp, glm::vec2 point);

// World texels the stamp (rim included) can touch, anywhere, and within the window.
TexelRect stampReach(const Stamp& stamp, const SnowWindow& window);
TexelRect stampBounds(const Stamp& stamp, const SnowWindow& window);
// The packed texel (deformation_texel.hpp) the stamp leaves at a world texel.
std::uint32_t stampTexel(const Stamp& stamp, const SnowWindow& window, glm::ivec2 texel);

// The snow the stamps are pressed into.
struct SnowCover {
  float depth = 0.f;  // local snow depth, metres
};

// Fresh snow (~100 kg/m³, docs/weather-simulation.md) packed under a foot or a wheel
// reaches ~300 kg/m³, so a print goes at most 2/3 of the way down; the last third
// is the packed snow at its bottom (seed 3.4: "pushed down to a base height slightly
// above the original terrain").
inline constexpr float kFreshSnowDensity = 100.f, kPackedSnowDensity = 300.f;
float deepestPrint(const SnowCover& cover);

// Rim height as a fraction of the print depth next to it, and a capsule's rim width as
// a fraction of its radius (a footprint's is FootShape::rimWidth): the snow pushed aside
// heaps up in a low ring (the shipped technique's "raised rims"). Chosen for looks.
inline constexpr float kRimHeightFraction = 0.25f, kRimWidthFraction = 0.6f;

// An adult boot sole, sized to read on the 4 cm map (four taps half a texel apart
// blur anything under two texels): 7.5 texels long; a 9 cm heel and an 11 cm ball,
// each deep over two to three texels; a 7 cm waist between them.
struct FootShape {
  float length = 0.30f;       // heel to toe
  float heelRadius = 0.045f;  // the heel is narrower than the ball of the foot
  float toeRadius = 0.055f;   // the ball and toe
  float waist = 0.035f;       // half the sole's width at the arch
  // Weight transfer: the heel strikes and the ball pushes off, the arch carries little.
  float toeDepthFraction = 0.9f;
  float archDepthFraction = 0.6f;
  // The snow pushed aside: a ridge 1.5 texels wide, so the map's taps keep it.
  float rimWidth = 0.06f;
};

// Oriented footprint centred at `centre`, heel behind, toe ahead along `heading`.
Stamp footprint(glm::vec2 centre, glm::vec2 heading, const FootShape& foot, const SnowCover& cover, float sink);
// A round body (or wheel of width 2 * radius) dragged from `from` to `to`.
Stamp capsule(glm::vec2 from, glm::vec2 to, float radius, const SnowCover& cover, float sink);

}  // namespace wg::snow
