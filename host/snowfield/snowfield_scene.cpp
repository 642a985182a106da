#include "host/snowfield/snowfield_scene.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "host/scene/horizon_apron.hpp"
#include "host/scene/shapes.hpp"

namespace wg::snow {

namespace {
// The base terrain the layer fades into sits just under the layer's border (which lies
// on the terrain's height map), so the two never fight for depth.
constexpr float kGroundClearance = 0.05f;
constexpr float kGroundSize = 160.f;   // metres: the camera's whole trip and the shadow map's reach
constexpr int kGroundCells = 80;       // 2 m: the hills' height map, texel centres on the vertices
// Beyond the ground a level apron reaches past the far plane (horizon_apron.hpp); the
// renderer's distance haze blends it into the sky, so no frame shows the world's edge.
// A hazy winter day: 1 - 1/e at 800 m, about 3 km visibility (Koschmieder: 3.9 x).
constexpr float kHazeDistance = 800.f;
// Hills: round bumps (height m, centre, radius m) on a plain at y = 0. The walkers
// cross a low rise; the camera's trip passes larger ones.
struct Hill {
  float height, x, z, radius;
};
constexpr Hill kHills[] = {{0.9f, 0.f, 5.f, 5.f},    {3.5f, -14.f, 22.f, 8.f}, {2.2f, 12.f, 18.f, 9.f},
                           {2.8f, 38.f, 14.f, 10.f}, {4.f, 62.f, 28.f, 11.f},  {2.f, 26.f, -14.f, 12.f},
                           {6.f, -34.f, 46.f, 16.f}, {1.5f, 50.f, -6.f, 7.f}};
constexpr float kEyeHeight = 2.2f, kLookAhead = 7.f, kFovDegrees = 55.f;
constexpr float kFineSquareAhead = 6.f;  // m: the frame's lower edge is 2 m ahead
constexpr float kCameraSpeed = 3.f;  // m/s while the camera travels
// The camera's trip (seconds): watch the prints form, travel 60 m along +x (out of the
// 41 m window), wait, come back.
constexpr double kLeaveAt = 12.0, kFarAt = 32.0, kReturnAt = 36.0, kBackAt = 56.0;
constexpr float kTripLength = 60.f;
const glm::vec3 kStart(0.f, kEyeHeight, -4.f);  // y: above the ground there
const glm::vec3 kTowardsSun(0.25f, 0.5f, 0.85f);
// Wind speed at windIntensity 1: the NWS blizzard threshold (docs/weather-simulation.md).
constexpr float kWindAtFullIntensity = 15.6f;

// Looking ahead along +z at the ground kLookAhead away.
scene::CameraPreset followCamera(glm::vec3 eye) {
  glm::vec2 ahead(eye.x, eye.z + kLookAhead);
  return {"follow", eye, {ahead.x, snowfieldGround(ahead.x, ahead.y), ahead.y}, kFovDegrees};
}

std::string fixed(double x, int decimals) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, x);
  return buf;
}

// The terrain height map the snow layer samples (snow_ground): heights over the
// ground's vertices, its zero at y = 0, as scene.cpp lays out the valley's.
void addTerrainMap(scene::Scene& s) {
  const int n = kGroundCells + 1;
  const float cell = kGroundSize / float(kGroundCells);
  float highest = 0.f;
  std::vector<float> heights(std::size_t(n) * n);
  for (int z = 0; z < n; ++z)
    for (int x = 0; x < n; ++x) {
      float h = snowfieldGround(-0.5f * kGroundSize + float(x) * cell, -0.5f * kGroundSize + float(z) * cell);
      heights[std::size_t(z) * n + x] = h;
      highest = std::max(highest, h);
    }
  s.terrainHeightResolution = n;
  s.terrainHeightOffset = 0.f;
  s.terrainHeightScale = std::max(highest, 1e-3f);
  for (float& h : heights) h /= s.terrainHeightScale;
  s.terrainHeights = std::move(heights);
  float origin = -0.5f * kGroundSize - 0.5f * cell, extent = kGroundSize + cell;
  s.terrainRegion = glm::vec4(origin, origin, 1.f / extent, 1.f / extent);
}

std::vector<Walker> scriptedWalkers() {
  Walker a, b;
  a.path = ScriptedPath({{-5.f, 1.f}, {5.f, 4.5f}}, 1.4f);
  b.path = ScriptedPath({{3.5f, -0.5f}, {-2.5f, 8.f}}, 1.2f);
  return {a, b};
}

PuffSettings litPuffs() {
  PuffSettings p;
  p.towardsSun = glm::normalize(kTowardsSun);
  return p;
}

Vehicle scriptedVehicle() {
  Vehicle v;
  v.path = ScriptedPath({{-12.f, 7.f}, {12.f, 5.f}}, 3.f);
  v.wheelWidth = 0.3f;
  return v;
}
}  // namespace

glm::vec3 snowfieldTowardsSun() { return glm::normalize(kTowardsSun); }

float snowfieldGround(float x, float z) {
  float h = 0.f;
  for (const Hill& hill : kHills) {
    float d2 = (x - hill.x) * (x - hill.x) + (z - hill.z) * (z - hill.z);
    h += hill.height * std::exp(-d2 / (hill.radius * hill.radius));
  }
  return h;
}

scene::Scene makeSnowfieldScene(const SnowfieldSettings& settings) {
  scene::Scene s;
  s.name = kSnowfieldScene;
  s.towardsSun = glm::normalize(kTowardsSun);
  auto add = [&](std::string name, std::string graph, scene::Mesh mesh, bool occludesSky) {
    scene::SceneObject o;
    o.name = std::move(name);
    o.graph = std::move(graph);
    o.mesh = std::move(mesh);
    o.occludesSky = occludesSky;
    s.objects.push_back(std::move(o));
  };
  scene::Mesh ground = scene::heightFieldTerrain(kGroundSize, kGroundCells,
                                                 [](float x, float z) { return snowfieldGround(x, z) - kGroundClearance; });
  scene::Mesh horizon = scene::horizonApron(ground, kGroundCells + 1, [](float, float) { return 0.f; });
  add("ground", "snowfield", std::move(ground), true);
  addTerrainMap(s);
  auto rock = [](std::uint32_t seed, float radius, float x, float sink, float z) {
    return scene::transformed(scene::rock(seed, radius),
                              glm::translate(glm::mat4(1.f), {x, snowfieldGround(x, z) + sink, z}));
  };
  add("rockNear", "rock", rock(11, 1.1f, 3.5f, 0.3f, 10.f), true);
  add("rockLeft", "rock", rock(23, 1.6f, -7.f, 0.4f, 14.f), true);
  add("rockFar", "rock", rock(37, 1.4f, 62.f, 0.3f, 8.f), true);
  // Movers' parts and the layer get their model matrix per frame (RenderRequest::objectModels).
  for (std::size_t i = 0; i < scriptedWalkers().size(); ++i)
    for (FigurePart& part : walkerParts("walker" + std::to_string(i))) add(part.name, "rock", std::move(part.mesh), false);
  for (FigurePart& part : vehicleParts("vehicle", scriptedVehicle())) add(part.name, "rock", std::move(part.mesh), false);
  add(kSnowLayerObject, kSnowLayerGraph, patchGridMesh(settings.grid), false);
  // The layer receives shadows but casts none: the sun's shadow map has texels of
  // ~8 cm here, too coarse for 10 cm prints (their normals shade them), and the
  // alpha-tested layer would run its whole material over the shadow map.
  s.objects.back().castsShadow = false;
  s.cameras.push_back(followCamera({kStart.x, snowfieldGround(kStart.x, kStart.z) + kEyeHeight, kStart.z}));
  // The apron stays out of the bounds, which the shadow and sky-exposure maps cover.
  scene::Bounds all;
  for (const auto& o : s.objects) all.include(scene::bounds(o.mesh));
  add("horizon", "snowfield", std::move(horizon), false);
  s.objects.back().castsShadow = false;
  s.objects.back().horizon = true;
  s.hazeDistance = kHazeDistance;
  // The layer moves with the camera: its reach over the whole trip.
  all.include(glm::vec3(kTripLength + 0.5f * settings.grid.extent(), 1.f, 0.f));
  s.boundsMin = all.min;
  s.boundsMax = all.max;
  return s;
}

SnowfieldAnimation::SnowfieldAnimation(vk::Context& ctx, const SnowfieldSettings& settings, const WeatherState& weather)
    : settings_(settings),
      weather_(weather),
      map_(ctx, settings.window, {kStart.x, kStart.z}),
      walkers_(scriptedWalkers()),
      vehicle_(scriptedVehicle()),
      puffs_(ctx, litPuffs()),
      bloom_(ctx) {}

// The first moment is just after a footfall (walker 0 steps at 2.68 s), so a puff hangs.
std::vector<double> SnowfieldAnimation::keyTimes() { return {2.8, 11.0, 24.0, 34.0, 58.0}; }

glm::vec3 SnowfieldAnimation::cameraEye(double t) const {
  double x = 0.0;
  if (t >= kLeaveAt && t < kFarAt) x = kCameraSpeed * (t - kLeaveAt);
  else if (t >= kFarAt && t < kReturnAt) x = kTripLength;
  else if (t >= kReturnAt && t < kBackAt) x = kTripLength - kCameraSpeed * (t - kReturnAt);
  glm::vec3 eye = kStart + glm::vec3(float(x), 0.f, 0.f);
  eye.y = snowfieldGround(eye.x, eye.z) + kEyeHeight;
  return eye;
}

void SnowfieldAnimation::step(double t0, double t1) {
  SnowCover cover{snowDepth(weather_, settings_.weather)};
  std::vector<Stamp> stamps;
  std::vector<glm::vec3> footfalls;
  // Puffs start where the foot breaks the snow surface (seed 3.3.1: at the impact): the
  // snow_layer graph raises the layer by the snow depth over the terrain.
  for (const auto& w : walkers_) {
    walkerStamps(w, t0, t1, cover, stamps);
    FootfallRange range = footfallsBetween(w, t0, t1);
    for (int k = range.first; k <= range.last; ++k) {
      glm::vec2 at = footfall(w, k);
      footfalls.push_back({at.x, snowfieldGround(at.x, at.y) + cover.depth, at.y});
    }
  }
  if (cover.depth > 0.f) puffs_.emit(footfalls);
  const auto& wind = weather_.conditions.windDirection;
  glm::vec2 windVelocity = glm::length(glm::vec2(wind[0], wind[1])) > 0.f
                               ? glm::normalize(glm::vec2(wind[0], wind[1])) * weather_.conditions.windIntensity * kWindAtFullIntensity
                               : glm::vec2(0.f);
  puffs_.simulate(t1 - t0, windVelocity);
  vehicleStamps(vehicle_, t0, t1, cover, stamps);
  glm::vec3 eye = cameraEye(t1);
  map_.follow({eye.x, eye.z});
  map_.apply(stamps);
  map_.refill(refillRate(weather_, settings_.weather), t1 - t0);
  stamps_ += stamps.size();
}

std::function<void(const ColourPassTargets&)> SnowfieldAnimation::postPasses() {
  return [this](const ColourPassTargets& t) {
    puffs_.record(t);
    bloom_.record(t.cmd, *t.colour);
  };
}

SnowfieldMoment SnowfieldAnimation::advanceTo(double seconds) {
  // The first footfalls land at t = 0: start the clock one frame early.
  if (time_ == 0.0) step(-settings_.frameSeconds, 0.0);
  while (time_ + 1e-9 < seconds) {
    double next = std::min(seconds, time_ + settings_.frameSeconds);
    step(time_, next);
    time_ = next;
  }
  SnowfieldMoment m;
  m.time = time_;
  glm::vec3 eye = cameraEye(time_);
  m.camera = followCamera(eye);
  // The layer's fine square is centred ahead of the camera, on the ground it looks at.
  glm::vec3 forward = m.camera.target - eye;
  forward.y = 0.f;
  glm::vec3 looked = eye + glm::normalize(forward) * kFineSquareAhead;
  m.objectModels[kSnowLayerObject] = glm::translate(glm::mat4(1.f), patchGridOrigin(settings_.grid, looked, 0.f));
  SnowCover cover{snowDepth(weather_, settings_.weather)};
  auto groundUnder = [&](float sink) {
    return FigureGround{snowfieldGround, cover.depth - std::min(sink, deepestPrint(cover))};
  };
  for (std::size_t i = 0; i < walkers_.size(); ++i) {
    const Walker& w = walkers_[i];
    poseWalker(w, "walker" + std::to_string(i), w.path.distanceAt(time_), groundUnder(w.sink), m.objectModels);
  }
  poseVehicle(vehicle_, "vehicle", vehicle_.path.distanceAt(time_), groundUnder(vehicle_.sink), m.objectModels);
  m.caption = {"t = " + fixed(time_, 1) + " s   camera x = " + fixed(eye.x, 0) + " m",
               std::to_string(map_.store().tileCount()) + " tiles in the print store, " + std::to_string(stamps_) +
                   " stamps so far"};
  return m;
}

}  // namespace wg::snow
