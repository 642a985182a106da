#include "host/scene/stage.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <glm/gtc/matrix_transform.hpp>

#include "compiler/weather_config.hpp"
#include "host/scene/horizon_apron.hpp"
#include "host/scene/orbit_camera.hpp"
#include "host/scene/shapes.hpp"

namespace wg::scene {

namespace {
// Ground grid: flat, so a few cells suffice; uv tiling as the bundled terrains.
constexpr int kGroundCells = 32;
constexpr float kGroundUvTiling = 8.f;
// The apron's reach in ground half-widths, at least: a framed camera stands about one
// ground width off, and sees 1.5 times its reach over the bounds.
constexpr float kStageHorizonReach = 12.f;
// Camera heights above the subject's centre (degrees) and the close-up's offset.
constexpr float kFrontElevation = 20.f;
constexpr float kSideElevation = 25.f;
constexpr float kCloseUpElevation = 15.f;
constexpr float kCloseUpAzimuth = 20.f;
constexpr float kCloseUpDistance = 0.6f;  // of the framing distance

Bounds objectBounds(const std::vector<SceneObject>& objects) {
  Bounds all;
  for (const SceneObject& o : objects) all.include(bounds(o.mesh, o.model));
  if (all.empty()) throw std::invalid_argument("a stage needs at least one object with vertices");
  return all;
}

SceneObject groundUnder(const Bounds& subject, float height, const std::string& graph) {
  glm::vec3 extent = subject.max - subject.min;
  float size = kStageGroundScale * std::max({extent.x, extent.z, 1.f});
  glm::vec3 centre(0.5f * (subject.min.x + subject.max.x), height, 0.5f * (subject.min.z + subject.max.z));
  Mesh mesh = heightFieldTerrain(size, kGroundCells, [](float, float) { return 0.f; }, kGroundUvTiling);
  SceneObject ground{"ground", graph, std::move(mesh), glm::translate(glm::mat4(1.f), centre), false, true};
  ground.parameters["weather.maxSnowHeight"] = stageSnowDepth(extent.y);
  return ground;
}

// The flat ground runs on, level, to the horizon: past the far plane of any framed or
// orbit view (pass_cameras.cpp: 1.5 times the camera's reach over the bounds).
SceneObject horizonAround(const SceneObject& ground) {
  HorizonApronSettings settings;
  settings.uvTiling = kGroundUvTiling;
  settings.reach = std::max(settings.reach, kStageHorizonReach * std::abs(ground.mesh.positions.front().x));
  Mesh apron = horizonApron(ground.mesh, kGroundCells + 1, [](float, float) { return 0.f; }, settings);
  SceneObject o{"horizon", ground.graph, std::move(apron), ground.model, false, false};
  o.horizon = true;
  o.parameters = ground.parameters;
  return o;
}

// The objects' world-space vertices above the ground: what the cameras must show.
std::vector<glm::vec3> visiblePoints(const std::vector<SceneObject>& objects, float ground) {
  std::vector<glm::vec3> points;
  for (const SceneObject& o : objects)
    for (glm::vec3 p : o.mesh.positions)
      if (glm::vec3 w = glm::vec3(o.model * glm::vec4(p, 1.f)); w.y >= ground) points.push_back(w);
  return points;
}

std::vector<CameraPreset> stageCameras(const std::vector<glm::vec3>& points, const Bounds& subject, glm::vec3 towardsSun) {
  glm::vec3 centre = 0.5f * (subject.min + subject.max);
  float sunAzimuth = glm::degrees(std::atan2(towardsSun.x, towardsSun.z));
  auto framed = [&](std::string name, float azimuth, float elevation, float scale = 1.f) {
    float distance = scale * framingDistance(points, centre, azimuth, elevation, kWideAspect);
    return orbitCamera(std::move(name), centre, azimuth, elevation, distance);
  };
  return {framed("front", 0.f, kFrontElevation), framed("sun-side", sunAzimuth, kSideElevation),
          framed("shade-side", sunAzimuth + 180.f, kSideElevation),
          framed("close-up", kCloseUpAzimuth, kCloseUpElevation, kCloseUpDistance)};
}
}  // namespace

float stageSnowDepth(float subjectHeight) {
  return std::min(WeatherConfig{}.maxSnowHeight, kStageSnowDepthShare * std::max(subjectHeight, 0.f));
}

Scene stageAround(std::string name, std::vector<SceneObject> objects, const StageOptions& options) {
  Bounds subject = objectBounds(objects);
  float ground = options.groundHeight.value_or(subject.min.y);
  subject.min.y = std::max(subject.min.y, ground);
  subject.max.y = std::max(subject.max.y, ground);

  Scene scene;
  scene.cameras = stageCameras(visiblePoints(objects, ground), subject, glm::normalize(options.towardsSun));
  scene.name = std::move(name);
  scene.towardsSun = glm::normalize(options.towardsSun);
  scene.objects = std::move(objects);
  scene.objects.push_back(groundUnder(subject, ground, options.groundGraph));
  Bounds all = objectBounds(scene.objects);
  scene.boundsMin = all.min;
  scene.boundsMax = all.max;
  scene.subject = subject;
  scene.objects.push_back(horizonAround(scene.objects.back()));  // outside the bounds
  scene.hazeDistance = kHorizonHazeDistance;
  return scene;
}

}  // namespace wg::scene
