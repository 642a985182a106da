// The reference host's specular sky light (host/sky_light_builder.hpp): the cube map the
// surfaces' wg_sky_reflection reads, level 0 the sky itself and each level after it the
// sky prefiltered for a rougher surface.
#include <gtest/gtest.h>

#include <string>

#include "host/sky_light_builder.hpp"
#include "nodes/pbr_shading.hpp"
#include "render_support.hpp"

namespace wg::testing {
namespace {

#define REQUIRE_VULKAN() \
  if (!renderContext()) GTEST_SKIP() << "no Vulkan driver (install mesa-vulkan-drivers)"

constexpr std::uint32_t kLevels = SkyLightBuilder::kReflectionLevels;
constexpr std::uint32_t kUp = 2, kDown = 3;  // Vulkan's +y and -y faces

std::uint32_t sizeOf(std::uint32_t level) { return SkyLightBuilder::kReflectionFaceSize >> level; }

FrameState clearSky() {
  FrameState frame;
  frame.skyColor = {0.25f, 0.45f, 0.9f};
  frame.ambientIntensity = 1.f;
  return frame;
}

glm::vec3 faceCentre(const SkyLightBuilder& sky, std::uint32_t level, std::uint32_t face) {
  const std::uint32_t s = sizeOf(level);
  return 0.25f * (sky.reflectionTexel(level, face, s / 2 - 1, s / 2 - 1) + sky.reflectionTexel(level, face, s / 2, s / 2 - 1) +
                  sky.reflectionTexel(level, face, s / 2 - 1, s / 2) + sky.reflectionTexel(level, face, s / 2, s / 2));
}

TEST(SkyReflection, FacesAreOrientedAsVulkanSamplesThem) {
  REQUIRE_VULKAN();
  SkyLightBuilder sky(*renderContext());
  sky.lightFor(clearSky());
  expectNoValidationMessages();
  // Face +x (direction (1, -t, -s)): rows above its middle look up at the sky, rows
  // below at the dim ground (0.35 of the horizon), whatever the column.
  const std::uint32_t s = sizeOf(0);
  for (std::uint32_t x : {0u, s / 2, s - 1}) {
    const glm::vec3 above = sky.reflectionTexel(0, 0, x, s / 2 - 8), below = sky.reflectionTexel(0, 0, x, s / 2 + 8);
    EXPECT_GT(above.g, 2.5f * below.g) << "column " << x;
  }
  // Overhead the clear sky is deep blue, at the horizon pale.
  const glm::vec3 zenith = faceCentre(sky, 0, kUp), horizon = sky.reflectionTexel(0, 4, s / 2, s / 2 - 2);
  EXPECT_GT(zenith.b / zenith.r, 1.3f * (horizon.b / horizon.r));
  EXPECT_GT(faceCentre(sky, 0, kUp).g, 2.f * faceCentre(sky, 0, kDown).g);
}

// Face +x at height t of its middle column (t in [-1, 1], down the face): between texel
// rows, interpolated as the sampler would.
glm::vec3 alongPlusX(const SkyLightBuilder& sky, std::uint32_t level, float t) {
  const std::uint32_t s = sizeOf(level);
  const float row = (t + 1.f) * 0.5f * float(s) - 0.5f;
  const auto r0 = static_cast<std::uint32_t>(row);
  const float f = row - float(r0);
  auto at = [&](std::uint32_t r) {
    return 0.5f * (sky.reflectionTexel(level, 0, s / 2 - 1, r) + sky.reflectionTexel(level, 0, s / 2, r));
  };
  return at(r0) * (1.f - f) + at(r0 + 1) * f;
}

TEST(SkyReflection, RougherLevelsBlurTheSkyAndKeepItsMean) {
  REQUIRE_VULKAN();
  SkyLightBuilder sky(*renderContext());
  sky.lightFor(clearSky());
  float previousContrast = 1e9f, contrastOfLevel0 = 0.f, meanOfLevel0 = 0.f;
  for (std::uint32_t level = 0; level < kLevels; ++level) {
    // 14 degrees above the horizon against 14 below: the step between sky and ground
    // softens with every level, as the lobe widens.
    const float contrast = alongPlusX(sky, level, -0.25f).g / alongPlusX(sky, level, 0.25f).g;
    EXPECT_LT(contrast, previousContrast) << "level " << level;
    previousContrast = contrast;
    if (level == 0) contrastOfLevel0 = contrast;
    // A normalised filter moves radiance about the sphere but keeps its mean.
    const std::uint32_t s = sizeOf(level);
    const std::vector<SkySample> texels = cubeSkySamples(s);  // a face's solid angles, row by row
    float mean = 0.f;
    for (std::uint32_t face = 0; face < 6; ++face)
      for (std::uint32_t y = 0; y < s; ++y)
        for (std::uint32_t x = 0; x < s; ++x) mean += sky.reflectionTexel(level, face, x, y).g * texels[y * s + x].solidAngle;
    mean /= 4.f * kPi;
    if (level == 0) meanOfLevel0 = mean;
    EXPECT_NEAR(mean, meanOfLevel0, 0.01f * meanOfLevel0) << "level " << level;
  }
  EXPECT_GT(contrastOfLevel0, 2.f) << "a mirror sees the horizon sharp";
  EXPECT_LT(previousContrast, 0.6f * contrastOfLevel0) << "the roughest level has blurred it";
}

TEST(SkyReflection, FollowsTheWeathersSkyAndIsBuiltOncePerSky) {
  REQUIRE_VULKAN();
  SkyLightBuilder sky(*renderContext());
  FrameState frame = clearSky();
  sky.lightFor(frame);
  const glm::vec3 clear = faceCentre(sky, 0, kUp);
  sky.lightFor(frame);
  EXPECT_EQ(sky.builds(), 1u);
  frame.precipitation = 0.8f;  // overcast: grey overhead
  sky.lightFor(frame);
  EXPECT_EQ(sky.builds(), 2u);
  const glm::vec3 overcast = faceCentre(sky, 0, kUp);
  EXPECT_GT(clear.b / clear.r, 1.5f * overcast.b / overcast.r);
  expectNoValidationMessages();
}

// wg_sky_reflection reads level 5 roughness: the host's last level is roughness 1.
TEST(SkyReflection, TheLibraryReadsTheLevelsTheHostBuilds) {
  const std::string library(kPbrShadingLibrary.glsl);
  EXPECT_NE(library.find("r, roughness * " + std::to_string(kLevels - 1) + ".0)"), std::string::npos);
}

}  // namespace
}  // namespace wg::testing
