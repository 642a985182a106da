// Precipitation near the viewer on lavapipe, validation on: heavy snow adds small bright
// flakes (not a veil) to the lit frame, rain streaks slant with the wind, the same time
// draws the same particles, and neither AOVs nor requests without it ever draw it.
#include <gtest/gtest.h>

#include <cmath>

#include "compiler/debug_views.hpp"
#include "render_support.hpp"

namespace wg {
namespace {

using namespace testing;

#define REQUIRE_VULKAN() \
  if (!renderContext()) GTEST_SKIP() << "no Vulkan driver (install mesa-vulkan-drivers)"

constexpr std::uint32_t kWidth = 256, kHeight = 144;
// A pixel counts as changed when its colour moved by more than this (display units).
constexpr float kChanged = 0.01f;

// A level camera at the valley's first preset: the upper half of the frame is sky,
// screen right is `right`, screen down is world down.
scene::CameraPreset levelCamera(const scene::Scene& scene, glm::vec3& right) {
  scene::CameraPreset camera = scene.cameras.front();
  glm::vec3 forward = camera.target - camera.eye;
  forward.y = 0.f;
  forward = glm::normalize(forward);
  camera.target = camera.eye + forward * 10.f;
  right = glm::normalize(glm::cross(forward, glm::vec3(0.f, 1.f, 0.f)));
  return camera;
}

RenderRequest fallRequest(SceneRenderer& renderer, float temperature, glm::vec2 wind, float windIntensity) {
  RenderRequest r;
  r.width = kWidth;
  r.height = kHeight;
  r.weather = weatherFor(renderer.scene());
  r.weather.conditions.temperature = temperature;
  r.weather.conditions.precipitation = 1.f;
  r.weather.conditions.windDirection = {wind.x, wind.y};
  r.weather.conditions.windIntensity = windIntensity;
  r.weather.time = 1234.5;
  glm::vec3 right;
  r.cameraPose = levelCamera(renderer.scene(), right);
  return r;
}

float luminance(glm::vec4 c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

struct Difference {
  std::vector<int> changed;  // per pixel: 1 where the particles changed it
  int count = 0, brighter = 0;
  double meanChange = 0.0;
};

Difference differenceOf(const RenderedFrame& without, const RenderedFrame& with) {
  Difference d;
  d.changed.assign(std::size_t(kWidth) * kHeight, 0);
  for (int y = 0; y < int(kHeight); ++y)
    for (int x = 0; x < int(kWidth); ++x) {
      glm::vec4 a = pixel(without, x, y), b = pixel(with, x, y);
      float change = glm::length(glm::vec3(b - a));
      if (change <= kChanged) continue;
      d.changed[std::size_t(y) * kWidth + x] = 1;
      ++d.count;
      d.brighter += luminance(b) > luminance(a);
      d.meanChange += change;
    }
  if (d.count) d.meanChange /= d.count;
  return d;
}

// How often a changed pixel has a changed neighbour `k` pixels down and to the right
// (sign +1) or down and to the left (sign -1), summed over k = 1..3: streaks falling to
// the right line up along +1.
long diagonalPairs(const Difference& d, int sign) {
  long pairs = 0;
  for (int k = 1; k <= 3; ++k)
    for (int y = 0; y + k < int(kHeight); ++y)
      for (int x = 0; x < int(kWidth); ++x) {
        int x2 = x + sign * k;
        if (x2 < 0 || x2 >= int(kWidth)) continue;
        pairs += d.changed[std::size_t(y) * kWidth + x] && d.changed[std::size_t(y + k) * kWidth + x2];
      }
  return pairs;
}

TEST(Precipitation, HeavySnowAddsSmallBrightFlakesNotAVeil) {
  REQUIRE_VULKAN();
  SceneRenderer& renderer = sceneRenderer("valley");
  RenderRequest request = fallRequest(renderer, -5.f, {1.f, 0.f}, 0.f);
  RenderedFrame without = renderer.render(request);
  request.precipitation = true;
  RenderedFrame with = renderer.render(request);
  expectNoValidationMessages();
  Difference d = differenceOf(without, with);
  const double share = double(d.count) / (kWidth * kHeight);
  // Thousands of flakes: visible, but most of the frame stays as it was.
  EXPECT_GT(share, 0.01) << d.count << " pixels changed";
  EXPECT_LT(share, 0.35) << d.count << " pixels changed";
  // White flakes lit by sun and sky, over sky and a snowless valley: brighter. Heavy
  // snow also fogs the valley towards the pale overcast sky (precipitationExtinction),
  // so a flake stands out less than over the clear view: 0.027 of full scale, was 0.03+.
  EXPECT_GT(d.brighter, 0.9 * d.count) << d.brighter << " of " << d.count << " changed pixels are brighter";
  EXPECT_GT(d.meanChange, 0.02);
  // Same time, same flakes.
  RenderedFrame again = renderer.render(request);
  EXPECT_EQ(again.rgba, with.rgba);
  // Another moment: the flakes have moved.
  request.weather.time += 2.0;
  EXPECT_NE(renderer.render(request).rgba, with.rgba);
}

TEST(Precipitation, RainStreaksSlantWithTheWind) {
  REQUIRE_VULKAN();
  SceneRenderer& renderer = sceneRenderer("valley");
  glm::vec3 right;
  levelCamera(renderer.scene(), right);
  for (int sign : {+1, -1}) {
    glm::vec2 wind = float(sign) * glm::vec2(right.x, right.z);  // blowing to screen right, then left
    RenderRequest request = fallRequest(renderer, 10.f, wind, 0.4f);
    RenderedFrame without = renderer.render(request);
    request.precipitation = true;
    RenderedFrame with = renderer.render(request);
    expectNoValidationMessages();
    Difference d = differenceOf(without, with);
    EXPECT_GT(d.count, int(0.005 * kWidth * kHeight)) << "wind " << sign;
    EXPECT_LT(d.count, int(0.5 * kWidth * kHeight)) << "wind " << sign;
    // Drops fall down and downwind: their streaks run down towards the wind's side.
    long downwind = diagonalPairs(d, sign), upwind = diagonalPairs(d, -sign);
    EXPECT_GT(double(downwind), 1.5 * double(upwind)) << "wind " << sign << ": " << downwind << " pairs along the wind, "
                                                      << upwind << " against it";
  }
}

TEST(Precipitation, NeverInAovsOrWhenNotAsked) {
  REQUIRE_VULKAN();
  SceneRenderer& renderer = sceneRenderer("valley");
  RenderRequest request = fallRequest(renderer, -5.f, {1.f, 0.f}, 0.5f);
  for (const auto& view : kDebugViews) {
    if (view.id == 0) continue;
    request.debugView = view.id;
    request.precipitation = false;
    RenderedFrame without = renderer.render(request);
    request.precipitation = true;
    EXPECT_EQ(renderer.render(request).rgba, without.rgba) << view.name;
  }
  expectNoValidationMessages();
  // No precipitation, nothing drawn.
  request.debugView = 0;
  request.weather.conditions.precipitation = 0.f;
  request.precipitation = false;
  RenderedFrame dry = renderer.render(request);
  request.precipitation = true;
  EXPECT_EQ(renderer.render(request).rgba, dry.rgba);
}

}  // namespace
}  // namespace wg
