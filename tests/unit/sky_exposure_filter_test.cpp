// The sky-exposure map's lookup (nodes/weather_model.hpp): each texel compared with the
// point, then filtered, so a tall occluder shelters no open ground beyond its own edge.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "nodes/weather_model.hpp"
#include "nodes/weather_shader_library.hpp"
#include "weather/sky_exposure_reach.hpp"

namespace wg {
namespace {

constexpr int kTexels = 64;
constexpr float kRock = 5.f;  // metres above the ground

// Texel columns below `edge` hold a 5 m occluder, the rest open ground at height 0.
std::vector<float> wallUpTo(int edge) {
  std::vector<float> heights(kTexels * kTexels, 0.f);
  for (int j = 0; j < kTexels; ++j)
    for (int i = 0; i < edge; ++i) heights[static_cast<std::size_t>(j) * kTexels + i] = kRock;
  return heights;
}

// Exposure of ground at texel coordinate x (the occluder's edge at x = 20).
float groundAt(float x) {
  return weather::filteredSkyExposure(wallUpTo(20), kTexels, {x / kTexels, 0.5f}, 0.f);
}

TEST(SkyExposureFilter, OpenGroundBeyondATallOccludersEdgeIsOpen) {
  EXPECT_FLOAT_EQ(groundAt(20.5f), 1.f);  // half a texel out: both neighbours are ground
  EXPECT_FLOAT_EQ(groundAt(24.f), 1.f);
  // A third of a texel out, a fifth of the footprint lies on the occluder: interpolated
  // heights (1 m there) would shelter the point completely.
  EXPECT_NEAR(groundAt(20.3f), 0.8f, 1e-4f);
}

TEST(SkyExposureFilter, GroundUnderTheOccluderIsSheltered) {
  EXPECT_FLOAT_EQ(groundAt(19.5f), 0.f);
  EXPECT_FLOAT_EQ(groundAt(2.f), 0.f);
  // The occluder's own top is open sky.
  EXPECT_FLOAT_EQ(weather::filteredSkyExposure(wallUpTo(20), kTexels, {10.f / kTexels, 0.5f}, kRock), 1.f);
}

// 0.2 m from an occluder is several texels on the bundled scenes (the 122 m rocks
// scene: 6 cm per texel), and the GLSL lookup uses the same texel count.
TEST(SkyExposureFilter, MapResolutionResolvesTwentyCentimetres) {
  EXPECT_LT(122.f / weather::kSkyExposureResolution, 0.1f);
  std::string glsl(kWeatherLibrary.glsl);
  EXPECT_NE(glsl.find("uv * " + std::to_string(weather::kSkyExposureResolution) + ".0"), std::string::npos);
}

TEST(SkyExposureFilter, AnEmptyMapIsOpenSky) {
  EXPECT_FLOAT_EQ(weather::filteredSkyExposure({}, 0, {0.5f, 0.5f}, 0.f), 1.f);
}

// Slanting snow under overhangs (weather/sky_exposure_reach.hpp), on a 20 m map at 10
// texels per metre over ground at height 0: a 3.6 m roof 2.8 m up keeps a dry core and
// gets snow under its eaves; a 5 m boulder's overhang gets snow; nothing gets more
// sheltered; under a sphere the bare ground is one soft-edged disc.
constexpr int kMap = 200;
constexpr float kTexelsPerMetre = 10.f;
const std::vector<float> kGround(kMap* kMap, 0.f);

float exposureAt(const std::vector<float>& heights, float xMetres, float zMetres, float y) {
  glm::vec2 uv(xMetres * kTexelsPerMetre / kMap, zMetres * kTexelsPerMetre / kMap);
  return weather::filteredSkyExposure(heights, kMap, uv, y);
}

std::vector<float> reached(const std::vector<float>& highest) {
  return reachUnderOverhangs(highest, kGround, kMap, kTexelsPerMetre, kTexelsPerMetre);
}

std::vector<float> squareAt(float height, float x0, float x1) {  // x and z in [x0, x1) metres
  std::vector<float> heights(kMap * kMap, 0.f);
  for (int j = 0; j < kMap; ++j)
    for (int i = 0; i < kMap; ++i) {
      float x = (i + 0.5f) / kTexelsPerMetre, z = (j + 0.5f) / kTexelsPerMetre;
      if (x >= x0 && x < x1 && z >= x0 && z < x1) heights[static_cast<std::size_t>(j) * kMap + i] = height;
    }
  return heights;
}

TEST(SkyExposureReach, ARoofKeepsADryCoreAndSnowReachesUnderItsEaves) {
  std::vector<float> roof = squareAt(2.8f, 8.2f, 11.8f);
  std::vector<float> under = reached(roof);
  EXPECT_FLOAT_EQ(exposureAt(under, 10.f, 10.f, 0.f), 0.f);  // the centre, 1.8 m from the edges
  EXPECT_FLOAT_EQ(exposureAt(under, 9.2f, 10.f, 0.f), 0.f);   // 1 m under the roof, beyond the 0.84 m reach
  EXPECT_FLOAT_EQ(exposureAt(under, 8.4f, 10.f, 0.f), 1.f);   // 0.2 m under the eaves: within half the reach
  EXPECT_FLOAT_EQ(exposureAt(roof, 8.4f, 10.f, 0.f), 0.f);    // before: sheltered
  EXPECT_FLOAT_EQ(exposureAt(under, 10.f, 10.f, 2.8f), 1.f);  // the roof itself
}

TEST(SkyExposureReach, SnowReachesUnderATallOverhangAndNothingGetsMoreSheltered) {
  std::vector<float> boulder = squareAt(5.f, 6.f, 14.f);
  std::vector<float> under = reached(boulder);
  EXPECT_FLOAT_EQ(exposureAt(under, 6.5f, 10.f, 0.f), 1.f);  // 0.5 m under a 5 m overhang (reach 1.5 m)
  EXPECT_GT(exposureAt(under, 6.9f, 10.f, 0.f), 0.8f);       // 0.9 m: thinning out
  EXPECT_FLOAT_EQ(exposureAt(under, 10.f, 10.f, 0.f), 0.f);  // 4 m in
  for (std::size_t t = 0; t < boulder.size(); ++t) ASSERT_LE(under[t], boulder[t]);
}

// A sphere of radius 1 resting on the ground at (10, 10): the ground's exposure from
// 1.5 m out to the contact point never rises again once it falls (no bare ring with
// snow inside it), falls by less than a third between points 5 cm apart (a soft edge),
// is full snow beyond the outline and bare at the contact point.
TEST(SkyExposureReach, UnderASphereTheBareGroundIsOneSoftEdgedDisc) {
  std::vector<float> sphere(kMap * kMap, 0.f);
  for (int j = 0; j < kMap; ++j)
    for (int i = 0; i < kMap; ++i) {
      const float x = (i + 0.5f) / kTexelsPerMetre - 10.f, z = (j + 0.5f) / kTexelsPerMetre - 10.f;
      const float r2 = x * x + z * z;
      if (r2 < 1.f) sphere[static_cast<std::size_t>(j) * kMap + i] = 1.f + std::sqrt(1.f - r2);
    }
  const std::vector<float> under = reached(sphere);
  float previous = 1.f;
  for (float r = 1.5f; r >= 0.f; r -= 0.05f) {
    const float e = exposureAt(under, 10.f + r, 10.f, 0.f);
    EXPECT_LE(e, previous + 1e-6f) << "snow again " << r << " m from the contact point, inside bare ground";
    EXPECT_LT(previous - e, 0.34f) << "a hard edge " << r << " m from the contact point";
    previous = e;
  }
  EXPECT_FLOAT_EQ(exposureAt(under, 11.05f, 10.f, 0.f), 1.f);
  EXPECT_FLOAT_EQ(exposureAt(under, 10.f, 10.f, 0.f), 0.f);
}

}  // namespace
}  // namespace wg
