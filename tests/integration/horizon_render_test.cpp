// The ground runs on to a hazy horizon (docs/runtime.md): seen from a gallery camera,
// the ground meets the sky by fading into it, never with a hard edge, while AOVs stay
// un-hazed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "compiler/debug_views.hpp"
#include "render_support.hpp"

namespace wg::testing {
namespace {

#define REQUIRE_VULKAN() \
  if (!renderContext()) GTEST_SKIP() << "no Vulkan driver (install mesa-vulkan-drivers)"

std::uint32_t albedoView() {
  for (const auto& v : kDebugViews)
    if (v.name == "albedo") return v.id;
  throw std::logic_error("no albedo view");
}

float fromSky(const RenderedFrame& frame, int x, int y, glm::vec4 sky) {
  glm::vec4 d = glm::abs(pixel(frame, x, y) - sky);
  return std::max({d.r, d.g, d.b});
}

// The road scene from its overview camera, which has the sky along the top of the frame.
RenderRequest overview(SceneRenderer& road, std::uint32_t width, std::uint32_t height) {
  RenderRequest request;
  request.camera = "overview";
  request.weather = weatherFor(road.scene());
  request.width = width;
  request.height = height;
  return request;
}

// The road scene's overview camera looks over the ground with the sky along the top of
// the frame. Going down each column from the sky, the ground starts as a faint tint of
// the sky and needs several rows to reach its own colour. A square of ground ending in
// the sky (no apron), or an apron cut off by the far plane without haze, goes from sky
// to ground in one or two rows.
TEST(Horizon, GroundFadesIntoTheSkyWithoutAnEdge) {
  REQUIRE_VULKAN();
  SceneRenderer& renderer = sceneRenderer("road");
  const RenderedFrame frame = renderer.render(overview(renderer, 192, 108));
  expectNoValidationMessages();
  const glm::vec4 sky = pixel(frame, 0, 0);
  constexpr float kTint = 0.01f, kOwnColour = 0.4f;
  constexpr int kMinFadeRows = 3;
  int soft = 0, columns = 0;
  for (int x = 0; x < int(frame.width); ++x) {
    EXPECT_LT(fromSky(frame, x, 0, sky), kTint) << "no sky above column " << x;
    int tinted = -1, own = -1;
    for (int y = 0; y < int(frame.height) && own < 0; ++y) {
      float d = fromSky(frame, x, y, sky);
      if (tinted < 0 && d > kTint) tinted = y;
      if (d > kOwnColour) own = y;
    }
    if (own < 0) continue;
    ++columns;
    soft += own - tinted >= kMinFadeRows;
  }
  ASSERT_GE(columns, int(frame.width) * 9 / 10) << "the ground should fill the lower frame";
  RecordProperty("soft_columns", soft);
  // The shelter's roof against the distant haze may end a column's fade early.
  EXPECT_GE(soft, columns * 9 / 10) << soft << " of " << columns << " columns fade into the sky";
}

// AOVs are the surface's own values, as the CPU evaluator computes them: the haze
// leaves them alone, far ground included.
TEST(Horizon, AovsAreNotHazed) {
  REQUIRE_VULKAN();
  SceneRenderer& renderer = sceneRenderer("road");
  RenderRequest request = overview(renderer, 64, 36);
  request.debugView = albedoView();
  request.onlyObject = "horizon";
  const RenderedFrame albedo = renderer.render(request);
  expectNoValidationMessages();
  int apron = 0;
  for (int y = 0; y < int(albedo.height); ++y)
    for (int x = 0; x < int(albedo.width); ++x)
      if (isSurface(albedo, x, y)) {
        ++apron;
        // Terrain albedo is far darker than the sky colour the haze would tend to.
        EXPECT_LT(pixel(albedo, x, y).b, 0.4f) << x << ", " << y;
      }
  EXPECT_GT(apron, 0);
}

}  // namespace
}  // namespace wg::testing
