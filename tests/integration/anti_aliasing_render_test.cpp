// Filtered textures and multisampling (docs/runtime.md): lit frames come close to the
// same view supersampled, while AOVs stay single-sampled and read textures at level 0,
// so their pixels are exactly what the CPU evaluator computes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "render_support.hpp"

namespace wg::testing {
namespace {

#define REQUIRE_VULKAN() \
  if (!renderContext()) GTEST_SKIP() << "no Vulkan driver (install mesa-vulkan-drivers)"

// The aliasing figure in linear colour: mean |small - (large box-downsampled)| over rgb,
// each clamped to [0, 1].
double aliasingFigure(const RenderedFrame& small, const RenderedFrame& large) {
  const int k = int(large.width / small.width);
  double sum = 0.0;
  for (int y = 0; y < int(small.height); ++y)
    for (int x = 0; x < int(small.width); ++x) {
      glm::vec4 mean(0.f);
      for (int j = 0; j < k; ++j)
        for (int i = 0; i < k; ++i) mean += glm::clamp(pixel(large, x * k + i, y * k + j), 0.f, 1.f);
      mean /= float(k * k);
      const glm::vec4 s = glm::clamp(pixel(small, x, y), 0.f, 1.f);
      for (int c = 0; c < 3; ++c) sum += std::fabs(s[c] - mean[c]);
    }
  return sum / (3.0 * small.width * small.height);
}

TEST(AntiAliasing, LavapipeDrawsLitFramesWithFourSamples) {
  REQUIRE_VULKAN();
  EXPECT_EQ(sceneRenderer("rocks").colourSamples(), 4u);
}

// CPU devices sample trilinear, without anisotropic filtering (vulkan/sampler_anisotropy.hpp).
TEST(AntiAliasing, LavapipeSamplesWithoutAnisotropy) {
  REQUIRE_VULKAN();
  if (renderContext()->properties().deviceType != VK_PHYSICAL_DEVICE_TYPE_CPU) GTEST_SKIP() << "not a CPU device";
  EXPECT_EQ(renderContext()->samplerAnisotropy(), 1.f);
}

// Mip-mapped textures and 4x multisampling keep a lit frame near the same view
// rendered 4x larger and box-downsampled: at most a third of the figure that level-0
// textures without multisampling gave (rocks 0.024, road 0.026; on lavapipe, trilinear
// since CPU devices went without anisotropy: rocks 0.0055, road 0.0066).
TEST(AntiAliasing, LitFramesAreCloseToTheSupersampledView) {
  REQUIRE_VULKAN();
  for (const char* name : {"rocks", "road"}) {
    SceneRenderer& renderer = sceneRenderer(name);
    RenderRequest request;
    request.weather = weatherFor(renderer.scene());
    request.width = 160;
    request.height = 90;
    const RenderedFrame small = renderer.render(request);
    expectNoValidationMessages();
    request.width = 640;
    request.height = 360;
    const RenderedFrame large = renderer.render(request);
    expectNoValidationMessages();
    const double figure = aliasingFigure(small, large);
    RecordProperty(std::string("aliasing_") + name, std::to_string(figure));
    EXPECT_LE(figure, 0.0075) << name;
  }
}

// render --samples 1 and bench-render --samples 1 (the MSAA cost): a renderer asked for
// one sample draws without multisampling, and its lit frame is further from the
// supersampled view than the 4x frame. The rocks are drawn alone, against the sky: the
// front view is ground from edge to edge (it runs on to the horizon), where texture
// filtering, not multisampling, sets the figure.
TEST(AntiAliasing, OneSampleDrawsWithoutMultisampling) {
  REQUIRE_VULKAN();
  SceneRenderer& fourSamples = sceneRenderer("rocks");
  SceneRenderer oneSample(*renderContext(), fourSamples.scene(), std::string(WG_SOURCE_DIR) + "/graphs",
                          VK_SAMPLE_COUNT_1_BIT);
  EXPECT_EQ(oneSample.colourSamples(), 1u);
  RenderRequest request;
  request.weather = weatherFor(fourSamples.scene());
  request.onlyObject = "rock-4";  // the middle boulder
  request.width = 640;
  request.height = 360;
  const RenderedFrame large = fourSamples.render(request);
  request.width = 160;
  request.height = 90;
  const double withMsaa = aliasingFigure(fourSamples.render(request), large);
  const double without = aliasingFigure(oneSample.render(request), large);
  expectNoValidationMessages();
  EXPECT_GT(without, 1.3 * withMsaa) << "1 sample " << without << ", 4 samples " << withMsaa;
}

// An AOV pixel is one surface at its centre: coverage (alpha) is 0 or 1, never a
// resolve's blend of a rock and the background.
TEST(AntiAliasing, AovsAreNotBlendedAtEdges) {
  REQUIRE_VULKAN();
  SceneRenderer& renderer = sceneRenderer("rocks");
  RenderRequest request;
  request.weather = weatherFor(renderer.scene());
  request.width = 320;
  request.height = 180;
  request.debugView = 1;  // albedo
  for (const auto& object : renderer.scene().objects)
    if (object.name.find("rock") != std::string::npos) {
      request.onlyObject = object.name;
      break;
    }
  ASSERT_FALSE(request.onlyObject.empty());
  const RenderedFrame frame = renderer.render(request);
  expectNoValidationMessages();
  int covered = 0;
  for (int y = 0; y < int(frame.height); ++y)
    for (int x = 0; x < int(frame.width); ++x) {
      const float a = pixel(frame, x, y).a;
      ASSERT_TRUE(a == 0.f || a == 1.f) << "alpha " << a << " at " << x << "," << y;
      covered += a == 1.f;
    }
  EXPECT_GT(covered, 20);
}

}  // namespace
}  // namespace wg::testing
