// The snowfield scene drawn by the runtime with the snow_layer graph and the
// deformation map bound (issue 5, §4, §6, §7), on lavapipe with validation on: prints
// show as packed snow, nothing ghosts where the camera travels, the prints are back
// after the round trip, and no snow means no prints.
#include "runtime/snow/snowfield_scene.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "compiler/debug_views.hpp"
#include "runtime/scene_renderer.hpp"

#include "tests/snow/snow_gpu_support.hpp"

namespace wg::snow {
namespace {

using testing::snowContext;

std::uint32_t albedoView() {
  for (const auto& v : kDebugViews)
    if (v.name == "albedo") return v.id;
  return 0;
}

struct Frames {
  std::vector<RenderedFrame> frames;  // at the requested times
};

// The layer alone, as albedo, at each time (small grid and image: the shading is per
// pixel from the 4 cm map, the grid only carries the displacement).
Frames renderLayer(float snowLevel, const std::vector<double>& times) {
  SnowfieldSettings settings;
  settings.grid.quadsPerPatch = 8;
  settings.frameSeconds = 0.1;
  WeatherState weather;
  weather.conditions.temperature = -6.f;
  glm::vec3 sun = snowfieldTowardsSun();
  weather.conditions.sunDirection = {sun.x, sun.y, sun.z};
  weather.levels.snow = snowLevel;
  SceneRenderer renderer(*snowContext(), makeSnowfieldScene(settings), std::string(WG_SOURCE_DIR) + "/graphs");
  SnowfieldAnimation animation(*snowContext(), settings, weather);
  renderer.setSnowDeformation(&animation.deformationImage());
  Frames out;
  for (double t : times) {
    SnowfieldMoment m = animation.advanceTo(t);
    RenderRequest request;
    request.width = 240;
    request.height = 135;
    request.weather = weather;
    request.debugView = albedoView();
    request.onlyObject = kSnowLayerObject;
    request.cameraPose = m.camera;
    request.objectModels = m.objectModels;
    out.frames.push_back(renderer.render(request));
  }
  return out;
}

// Pixels of the layer whose albedo is the packed snow's rather than fresh snow's
// (graphs/snow_layer.json: red 0.62 packed, 0.9 fresh).
int packedPixels(const RenderedFrame& f) {
  constexpr float kBetween = 0.76f;
  int n = 0;
  for (std::size_t i = 0; i < f.rgba.size(); i += 4)
    if (f.rgba[i + 3] > 0.f && f.rgba[i] < kBetween) ++n;
  return n;
}

using Snowfield = testing::ValidatedGpuTest;

TEST_F(Snowfield, PrintsShowAsPackedSnowAndComeBackAfterTheRoundTrip) {
  // Prints formed; the camera 60 m away (out of the window); back at the start.
  Frames r = renderLayer(1.f, {11.0, 34.0, 58.0});
  int before = packedPixels(r.frames[0]), away = packedPixels(r.frames[1]), back = packedPixels(r.frames[2]);
  EXPECT_GT(before, 200) << "trails and ruts should cover hundreds of pixels";
  EXPECT_EQ(away, 0) << "stored prints must not ghost into the window elsewhere";
  EXPECT_EQ(back, before);
  double sum = 0.0;
  float worst = 0.f;
  for (std::size_t i = 0; i < r.frames[0].rgba.size(); ++i) {
    float d = std::abs(r.frames[0].rgba[i] - r.frames[2].rgba[i]);
    sum += d;
    worst = std::max(worst, d);
  }
  EXPECT_LT(sum / double(r.frames[0].rgba.size()), 1e-4);
  EXPECT_LT(worst, 0.05f);
}

TEST_F(Snowfield, NoSnowNoPrints) {
  Frames r = renderLayer(0.f, {11.0});
  EXPECT_EQ(packedPixels(r.frames[0]), 0);
}

}  // namespace
}  // namespace wg::snow
