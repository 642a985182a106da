// The sky's diffuse light as spherical harmonics (host/sky_irradiance.hpp): the cube's
// samples cover the sphere, a sky of one radiance gives exactly that irradiance at every
// normal (the constant ambient it replaced), and each band carries its clamped-cosine
// factor (Ramamoorthi and Hanrahan, eq. 8-9).
#include <gtest/gtest.h>

#include <functional>
#include <numbers>

#include "host/sky_irradiance.hpp"

namespace wg {
namespace {

constexpr std::uint32_t kFaceSize = 16;

SkyIrradiance projected(const std::function<glm::vec3(glm::vec3)>& sky) {
  const std::vector<SkySample> samples = cubeSkySamples(kFaceSize);
  std::vector<glm::vec3> radiance;
  for (const SkySample& s : samples) radiance.push_back(sky(s.direction));
  return projectSkyIrradiance(samples, radiance);
}

const glm::vec3 kNormals[] = {{0.f, 1.f, 0.f},  {0.f, -1.f, 0.f}, {1.f, 0.f, 0.f},   {0.f, 0.f, -1.f},
                              {0.6f, 0.8f, 0.f}, {0.f, -0.6f, 0.8f}, {0.48f, 0.6f, -0.64f}};

TEST(SkyIrradiance, TheCubesSamplesCoverTheSphereOnce) {
  double total = 0.0;
  for (const SkySample& s : cubeSkySamples(kFaceSize)) {
    EXPECT_NEAR(glm::length(s.direction), 1.f, 1e-6f);
    total += s.solidAngle;
  }
  EXPECT_NEAR(total, 4.0 * std::numbers::pi, 1e-5);
}

TEST(SkyIrradiance, ASkyOfOneRadianceGivesThatIrradianceEverywhere) {
  const glm::vec3 radiance(0.36f, 0.44f, 0.58f);
  const SkyIrradiance sh = projected([&](glm::vec3) { return radiance; });
  for (glm::vec3 n : kNormals) {
    glm::vec3 e = skyIrradianceAt(sh, glm::normalize(n));
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(e[c], radiance[c], 1e-6f) << n.x << "," << n.y << "," << n.z;
  }
}

// Radiance 1 above the horizon and 0 below: irradiance pi facing up, pi/2 sideways and
// 0 facing down. The first two bands carry all of it (band 2's 3y^2 - 1 integrates to 0
// over the half sphere), so this checks band 1's factor 2/3 exactly.
TEST(SkyIrradiance, AnUpperHemisphereLightsUpFacingFacesFullyAndSideFacesHalf) {
  const SkyIrradiance sh = projected([](glm::vec3 d) { return glm::vec3(d.y > 0.f ? 1.f : 0.f); });
  EXPECT_NEAR(skyIrradianceAt(sh, {0.f, 1.f, 0.f}).g, 1.f, 1e-3f);
  EXPECT_NEAR(skyIrradianceAt(sh, {1.f, 0.f, 0.f}).g, 0.5f, 1e-3f);
  EXPECT_NEAR(skyIrradianceAt(sh, {0.f, -1.f, 0.f}).g, 0.f, 1e-3f);
}

// A sky that is itself a band-2 harmonic comes back scaled by the cosine's band-2
// factor A_2 / pi = 1/4, whatever the normal; and band 2 stays in band 2.
TEST(SkyIrradiance, ABandTwoSkyIsScaledByAQuarter) {
  auto band2 = [](glm::vec3 d) { return 3.f * d.y * d.y - 1.f + 2.f * d.x * d.z; };
  const SkyIrradiance sh = projected([&](glm::vec3 d) { return glm::vec3(band2(d)); });
  for (glm::vec3 n : kNormals) {
    n = glm::normalize(n);
    EXPECT_NEAR(skyIrradianceAt(sh, n).r, 0.25f * band2(n), 2e-3f) << n.x << "," << n.y << "," << n.z;
  }
}

TEST(SkyIrradiance, TheFrameBlockHoldsTheCoefficientsInOrder) {
  SkyIrradiance sh;
  for (std::size_t i = 0; i < 9; ++i) sh.coefficients[i] = glm::vec3(float(i), 0.5f, -1.f);
  FrameState frame;
  writeSkyIrradiance(sh, frame);
  for (std::size_t i = 0; i < 9; ++i) {
    EXPECT_EQ(frame.skyIrradiance[i][0], float(i));
    EXPECT_EQ(frame.skyIrradiance[i][1], 0.5f);
    EXPECT_EQ(frame.skyIrradiance[i][2], -1.f);
    EXPECT_EQ(frame.skyIrradiance[i][3], 0.f);
  }
}

}  // namespace
}  // namespace wg
