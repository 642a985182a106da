// Stages (stageAround), orbit cameras and the preview stand of `render --material`:
// the ground under the objects, the four framed cameras, and the stand's shapes,
// roof and probes.
#include "host/scene/stage.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include <glm/gtc/matrix_transform.hpp>

#include "host/scene/orbit_camera.hpp"
#include "host/scene/preview_stand.hpp"
#include "host/scene/shapes.hpp"

namespace wg::scene {
namespace {

constexpr float kAspect = 16.f / 9.f;

// Where a world point lands in normalised device coordinates of a 16:9 frame.
glm::vec3 ndc(const CameraPreset& c, glm::vec3 p) {
  glm::mat4 view = glm::lookAt(c.eye, c.target, glm::vec3(0.f, 1.f, 0.f));
  glm::vec4 clip = glm::perspective(glm::radians(c.fovYDegrees), kAspect, 0.1f, 600.f) * view * glm::vec4(p, 1.f);
  return glm::vec3(clip) / clip.w;
}

std::vector<SceneObject> twoBoxes() {
  return {{"a", "rock", box({-1.f, 0.f, -1.f}, {1.f, 2.f, 1.f})},
          {"b", "rock", box({3.f, 0.f, 0.f}, {4.f, 1.f, 1.f}), glm::translate(glm::mat4(1.f), {0.f, 0.f, -2.f})}};
}

TEST(Stage, AddsTheGroundUnderTheObjects) {
  Scene s = stageAround("pair", twoBoxes());
  ASSERT_EQ(s.objects.size(), 4u);
  EXPECT_EQ(s.objects[0].name, "a");
  EXPECT_EQ(s.objects[1].name, "b");
  const SceneObject& ground = s.objects[2];
  EXPECT_EQ(ground.name, "ground");
  EXPECT_EQ(ground.graph, "terrain");
  EXPECT_FALSE(ground.castsShadow);
  EXPECT_TRUE(ground.occludesSky);
  Bounds g = bounds(ground.mesh, ground.model);
  EXPECT_NEAR(g.min.y, 0.f, 1e-6f);  // the objects' lowest point
  EXPECT_NEAR(g.max.y, 0.f, 1e-6f);
  ASSERT_TRUE(s.subject);
  EXPECT_LT(glm::distance(s.subject->min, glm::vec3(-1.f, 0.f, -2.f)), 1e-5f);
  EXPECT_LT(glm::distance(s.subject->max, glm::vec3(4.f, 2.f, 1.f)), 1e-5f);
  // The ground reaches well beyond the objects on every side.
  EXPECT_LT(g.min.x, s.subject->min.x - 5.f);
  EXPECT_GT(g.max.z, s.subject->max.z + 5.f);
  EXPECT_LT(glm::distance(s.boundsMin, g.min), 1e-5f);
  EXPECT_NEAR(glm::length(s.towardsSun), 1.f, 1e-5f);
  EXPECT_TRUE(s.probes.empty());
  EXPECT_TRUE(s.terrainHeights.empty());
  // Then the level apron out to the horizon, past any far plane, with haze to hide its end.
  const SceneObject& horizon = s.objects[3];
  EXPECT_EQ(horizon.name, "horizon");
  EXPECT_TRUE(horizon.horizon);
  EXPECT_EQ(horizon.graph, "terrain");
  Bounds h = bounds(horizon.mesh, horizon.model);
  EXPECT_NEAR(h.min.y, 0.f, 1e-6f);
  EXPECT_NEAR(h.max.y, 0.f, 1e-6f);
  EXPECT_LT(h.min.x, -1400.f);
  EXPECT_GT(h.max.z, 1400.f);
  EXPECT_GT(s.hazeDistance, 0.f);
}

TEST(Stage, HonoursTheGroundHeightSunAndGraph) {
  StageOptions options;
  options.groundHeight = 0.5f;
  options.groundGraph = "my/ground.json";
  options.towardsSun = {0.f, 2.f, 0.f};
  Scene s = stageAround("pair", twoBoxes(), options);
  const SceneObject* ground = s.find("ground");
  ASSERT_TRUE(ground);
  Bounds g = bounds(ground->mesh, ground->model);
  EXPECT_NEAR(g.min.y, 0.5f, 1e-6f);
  EXPECT_EQ(ground->graph, "my/ground.json");
  EXPECT_EQ(s.find("horizon")->graph, "my/ground.json");
  EXPECT_NEAR(s.subject->min.y, 0.5f, 1e-6f);  // cut off at the ground
  EXPECT_LT(glm::distance(s.towardsSun, glm::vec3(0.f, 1.f, 0.f)), 1e-6f);
}

// The stand shows the model: its ground's snow is at most a quarter of the subject's
// height deep (weather.maxSnowHeight on the ground and the horizon), the presets' 25 cm
// from 1 m up.
TEST(Stage, TheGroundsSnowNeverBuriesASmallModel) {
  Scene small = stageAround("pebble", {{"pebble", "rock", box({0.f, 0.f, 0.f}, {0.1f, 0.1f, 0.1f})}});
  EXPECT_FLOAT_EQ(small.find("ground")->parameters.at("weather.maxSnowHeight"), 0.025f);
  EXPECT_FLOAT_EQ(small.find("horizon")->parameters.at("weather.maxSnowHeight"), 0.025f);
  EXPECT_TRUE(small.find("pebble")->parameters.empty());  // the model keeps its own
  Scene tall = stageAround("pair", twoBoxes());
  EXPECT_FLOAT_EQ(tall.find("ground")->parameters.at("weather.maxSnowHeight"), 0.25f);
  EXPECT_FLOAT_EQ(stageSnowDepth(1.f), 0.25f);
  EXPECT_FLOAT_EQ(stageSnowDepth(0.f), 0.f);
}

TEST(Stage, RejectsNoObjects) {
  EXPECT_THROW(stageAround("empty", {}), std::invalid_argument);
  EXPECT_THROW(stageAround("empty", {{"nothing", "rock", Mesh{}}}), std::invalid_argument);
}

TEST(Stage, FourCamerasFrameEveryObjectVertex) {
  Scene s = stageAround("pair", twoBoxes());
  std::vector<std::string> names;
  for (const auto& c : s.cameras) names.push_back(c.name);
  EXPECT_EQ(names, (std::vector<std::string>{"front", "sun-side", "shade-side", "close-up"}));
  glm::vec3 centre = 0.5f * (s.subject->min + s.subject->max);
  for (const auto& c : s.cameras) {
    EXPECT_LT(glm::distance(c.target, centre), 1e-5f) << c.name;
    if (c.name == "close-up") continue;  // closer on purpose
    float widest = 0.f;
    for (std::size_t i = 0; i + 2 < s.objects.size(); ++i)  // not the ground and its apron
      for (glm::vec3 p : transformed(s.objects[i].mesh, s.objects[i].model).positions) {
        glm::vec3 d = ndc(c, p);
        ASSERT_LE(std::abs(d.x), 1.f) << c.name;
        ASSERT_LE(std::abs(d.y), 1.f) << c.name;
        widest = std::max({widest, std::abs(d.x), std::abs(d.y)});
      }
    EXPECT_GT(widest, 0.8f) << c.name << " frames the objects tightly";
  }
  glm::vec3 front = s.camera("front")->eye - centre, sun = s.camera("sun-side")->eye - centre;
  EXPECT_GT(front.z, 0.f);
  EXPECT_NEAR(front.x, 0.f, 1e-4f);
  EXPECT_GT(glm::dot(glm::normalize(glm::vec2(sun.x, sun.z)), glm::normalize(glm::vec2(s.towardsSun.x, s.towardsSun.z))),
            0.999f);
  glm::vec3 shade = s.camera("shade-side")->eye - centre;
  EXPECT_LT(glm::dot(glm::vec2(shade.x, shade.z), glm::vec2(sun.x, sun.z)), 0.f);
  EXPECT_LT(glm::length(s.camera("close-up")->eye - centre), glm::length(front));
}

TEST(OrbitCamera, TurnsFromPlusZTowardsPlusX) {
  CameraPreset c = orbitCamera("o", {1.f, 2.f, 3.f}, 90.f, 0.f, 10.f);
  EXPECT_LT(glm::distance(c.eye, glm::vec3(11.f, 2.f, 3.f)), 1e-4f);
  c = orbitCamera("o", {0.f, 0.f, 0.f}, 0.f, 30.f, 2.f);
  EXPECT_LT(glm::distance(c.eye, glm::vec3(0.f, 1.f, std::sqrt(3.f))), 1e-4f);
}

TEST(OrbitCamera, FramesTheSceneBoundsUnlessADistanceIsGiven) {
  Scene s;
  s.boundsMin = {-10.f, 0.f, -10.f};
  s.boundsMax = {10.f, 4.f, 10.f};
  CameraPreset framed = orbitCamera(s, {30.f, 20.f, std::nullopt}, kAspect);
  EXPECT_LT(glm::distance(framed.target, glm::vec3(0.f, 2.f, 0.f)), 1e-5f);
  for (int k = 0; k < 8; ++k) {
    glm::vec3 corner((k & 1) ? 10.f : -10.f, (k & 2) ? 4.f : 0.f, (k & 4) ? 10.f : -10.f);
    glm::vec3 d = ndc(framed, corner);
    EXPECT_LE(std::abs(d.x), 1.f);
    EXPECT_LE(std::abs(d.y), 1.f);
  }
  CameraPreset given = orbitCamera(s, {30.f, 20.f, 7.f}, kAspect);
  EXPECT_NEAR(glm::distance(given.eye, given.target), 7.f, 1e-4f);
  s.subject = Bounds{{0.f, 0.f, 0.f}, {2.f, 2.f, 2.f}};  // a stage frames its subject
  EXPECT_LT(glm::distance(orbitCamera(s, {0.f, 0.f, std::nullopt}, kAspect).target, glm::vec3(1.f)), 1e-5f);
}

TEST(PreviewStand, ShowsTheMaterialOnFourShapesBesideARoof) {
  Scene s = previewStand("my/material.json", "stand-material");
  EXPECT_EQ(s.name, "stand-material");
  for (auto name : previewStandSubjects()) {
    const SceneObject* o = s.find(name);
    ASSERT_TRUE(o) << name;
    EXPECT_EQ(o->graph, "my/material.json");
    EXPECT_GE(bounds(o->mesh, o->model).min.y, -0.2f) << name << " stands on the ground";
  }
  ASSERT_TRUE(s.find("roof"));
  ASSERT_TRUE(s.find("ground"));
  EXPECT_EQ(s.find("ground")->graph, "terrain");
  // The cube's overhanging faces: some of its normals point down.
  const SceneObject* cube = s.find("cube");
  bool overhangs = false;
  for (glm::vec3 n : transformed(cube->mesh, cube->model).normals) overhangs = overhangs || n.y < -0.5f;
  EXPECT_TRUE(overhangs);
  for (const char* camera : {"front", "sun-side", "shade-side", "close-up"}) EXPECT_TRUE(s.camera(camera)) << camera;
  ASSERT_EQ(s.probes.size(), 2u);
  for (const Probe& p : s.probes) {
    EXPECT_EQ(p.object, "ground");
    EXPECT_NE(std::find(p.visibleFrom.begin(), p.visibleFrom.end(), "front"), p.visibleFrom.end()) << p.name;
  }
  EXPECT_EQ(s.probes[0].expect, "sheltered");
  EXPECT_EQ(s.probes[1].expect, "open");
}

}  // namespace
}  // namespace wg::scene
