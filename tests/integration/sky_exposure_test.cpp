// The sky-exposure map of a real scene (host/sky_exposure_map.cpp): snow reaches the
// foot of a boulder on a slope, under its overhang too, while the ground the boulder
// stands on stays sheltered. Reads the renderer's map on the CPU as the shaders do; no
// frame is drawn.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>

#include "render_support.hpp"

namespace wg::testing {
namespace {

// World height of the terrain at (x, z), from the scene's height map.
float groundAt(const SceneRenderer& renderer, float x, float z) {
  const scene::Scene& s = renderer.scene();
  glm::vec2 uv = (glm::vec2(x, z) - glm::vec2(s.terrainRegion.x, s.terrainRegion.y)) *
                 glm::vec2(s.terrainRegion.z, s.terrainRegion.w);
  return s.terrainHeightOffset + s.terrainHeightScale * terrainField(renderer).sample(uv.x, uv.y);
}

TEST(SkyExposureMap, SnowReachesTheFootOfABoulderOnASlope) {
  if (!renderContext()) GTEST_SKIP() << "no Vulkan driver (install mesa-vulkan-drivers)";
  SceneRenderer& renderer = sceneRenderer("rocks");
  // The middle boulder (5.5 m, at the origin on the 31 degree slope falling towards +z):
  // its outline seen from above, straight downhill of its centre.
  const scene::SceneObject* boulder = nullptr;
  for (const auto& object : renderer.scene().objects)
    if (object.graph == "rock" && glm::length(glm::vec2(object.model[3].x, object.model[3].z)) < 1.f) boulder = &object;
  ASSERT_NE(boulder, nullptr);
  const glm::vec3 centre(boulder->model[3]);
  float outline = -std::numeric_limits<float>::max();
  for (glm::vec3 v : boulder->mesh.positions) {
    glm::vec3 w(boulder->model * glm::vec4(v, 1.f));
    if (std::abs(w.x - centre.x) < 0.15f) outline = std::max(outline, w.z);
  }
  ASSERT_GT(outline, centre.z + 4.f);
  auto exposureOfGround = [&](float z) {
    return skyExposureAt(renderer, {centre.x, groundAt(renderer, centre.x, z), z}, {0.f, 1.f, 0.f});
  };
  // Open ground from 0.2 m beyond the outline is open sky; so is the ground half a metre
  // under the overhang, where slanting snow reaches (without the reach it is sheltered:
  // a metre-wide bare skirt along the boulder's downhill foot).
  for (float d : {0.2f, 0.5f, 1.f, 2.f}) EXPECT_GT(exposureOfGround(outline + d), 0.99f) << d << " m outside";
  EXPECT_GT(exposureOfGround(outline - 0.5f), 0.99f) << "0.5 m under the overhang";
  // The ground under the boulder's body stays sheltered.
  EXPECT_LT(exposureOfGround(outline - 3.f), 0.01f);
}

}  // namespace
}  // namespace wg::testing
