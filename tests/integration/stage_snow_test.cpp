// The stand shows the model under snow: a 10 cm model's ground gets 2.5 cm of snow, not
// the presets' 25 cm that would hide it, through the ground material's own parameter
// (SceneObject::parameters, uploaded over the reflected default).
#include <gtest/gtest.h>

#include <cmath>

#include "compiler/debug_views.hpp"
#include "host/scene/shapes.hpp"
#include "host/scene/stage.hpp"
#include "render_support.hpp"

namespace wg {
namespace {

using namespace testing;

constexpr std::uint32_t kWidth = 160, kHeight = 90;

std::uint32_t positionView() {
  for (const auto& v : kDebugViews)
    if (v.name == "position") return v.id;
  return 0;
}

TEST(StageSnow, ASmallModelStandsInShallowSnowInsteadOfUnderIt) {
  if (!renderContext()) GTEST_SKIP() << "no Vulkan driver (install mesa-vulkan-drivers)";
  const float size = 0.1f;
  scene::Scene stage =
      scene::stageAround("pebble", {{"pebble", "rock", scene::box({-size / 2, 0.f, -size / 2}, {size / 2, size, size / 2})}});
  // From 45 degrees above, outside any snow: the framed cameras of so small a subject
  // stand inside a 25 cm layer, and see through its back faces.
  stage.cameras.push_back({"above", {0.f, 0.5f, 0.5f}, {0.f, 0.5f * size, 0.f}, 40.f});
  SceneRenderer renderer(*renderContext(), std::move(stage), std::string(WG_SOURCE_DIR) + "/graphs");
  RenderRequest r;
  r.width = kWidth;
  r.height = kHeight;
  r.debugView = positionView();
  r.camera = "above";
  r.weather.conditions.temperature = -5.f;
  r.weather.levels.snow = 1.f;
  RenderedFrame frame = renderer.render(r);
  expectNoValidationMessages();
  // The middle of the box's front face, above the shallow snow, is what the camera sees
  // there: with 25 cm of snow in front of it, the snow would be.
  const glm::vec3 faceMiddle(0.f, 0.6f * size, size / 2);
  auto at = project(renderer.viewProjection("above", kWidth, kHeight), faceMiddle, kWidth, kHeight);
  ASSERT_TRUE(at.has_value());
  const glm::vec4 seen = pixel(frame, at->x, at->y);
  EXPECT_NEAR(seen.z, size / 2, 0.01f) << "seen at y " << seen.y;
  EXPECT_NEAR(seen.y, faceMiddle.y, 0.02f);
}

}  // namespace
}  // namespace wg
