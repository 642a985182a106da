// The bundled validation scenes of the Vulkan runtime: deterministic, procedural, each
// built to make one or more weather behaviours visible (snow by height and sun side,
// river ice from the banks, puddles only on flat road, nothing under a shelter).
#pragma once
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "host/scene/mesh.hpp"

namespace wg::scene {

struct SceneObject {
  std::string name;
  // A bundled graph's stem ("rock", "terrain", "grass", "foliage", "river", "road",
  // "snowfield": graphs/<graph>.json), or, ending in ".json", a graph file's path
  // (absolute or relative to the working directory). See graph_path.hpp.
  std::string graph;
  Mesh mesh;
  glm::mat4 model{1.f};
  bool castsShadow = true;
  bool occludesSky = true;  // drawn into the sky-exposure (occluder height) map
  // Ground out to the horizon (horizon_apron.hpp): outside boundsMin/Max, which the
  // shadow and sky-exposure maps cover, so it neither casts shadows nor shelters.
  bool horizon = false;
  // Material parameters over the graph's defaults, by the reflection's names; a name
  // the compiled material lacks (an unweathered variant has no weather.*) is skipped.
  std::map<std::string, float> parameters;
};

struct CameraPreset {
  std::string name;
  glm::vec3 eye{0.f}, target{0.f};
  float fovYDegrees = 50.f;
};

// A world-space point on a generated surface that pixel-sampling tests look at, with
// what the weather should do there.
struct Probe {
  std::string name;
  glm::vec3 position{0.f};  // on the surface of `object`'s mesh (world space)
  glm::vec3 normal{0.f, 1.f, 0.f};  // the interpolated vertex normal there (unit, world space)
  // "sheltered", "open", "flat-road", "sloped-road", "river-bank", "river-centre",
  // "rock-top", "rock-sun-side" or "rock-shade-side".
  std::string expect;
  std::string object;  // name of the SceneObject the point lies on
  // Cameras that see the point in a square viewport (wider ones see more): inside the
  // frustum, facing the camera and not hidden by any mesh (alpha cards count as solid).
  std::vector<std::string> visibleFrom;
};

struct Scene {
  std::string name;
  std::vector<SceneObject> objects;
  std::vector<CameraPreset> cameras;
  glm::vec3 towardsSun{0.f, 1.f, 0.f};  // unit
  glm::vec3 boundsMin{0.f}, boundsMax{0.f};  // of every object, world space
  // What cameras frame and orbit round: the objects a stage stands around (see
  // stage.hpp). Unset (the bundled scenes): the whole bounds.
  std::optional<Bounds> subject;
  // World xz -> height-map uv as frame_terrainRegion: (xz - region.xy) * region.zw.
  // Texel centres sit exactly on the terrain mesh's vertices.
  glm::vec4 terrainRegion{0.f};
  int terrainHeightResolution = 0;
  // Row-major (row = z, column = x), terrainHeightResolution^2 heights in [0, 1]:
  // world y = terrainHeightOffset + terrainHeightScale * height.
  std::vector<float> terrainHeights;
  float terrainHeightScale = 1.f;   // metres per unit
  float terrainHeightOffset = 0.f;  // world y of height 0 (the terrain's lowest point)
  std::vector<Probe> probes;
  // Distance haze (host/distance_haze_pass.hpp) on lit frames: metres over which
  // surfaces fade 1 - 1/e of the way to the sky. 0: none.
  float hazeDistance = 0.f;

  const SceneObject* find(std::string_view objectName) const;
  const CameraPreset* camera(std::string_view cameraName) const;
  Bounds framedBounds() const;  // `subject`, else the bounds
};

// The bundled scenes, in table order: "valley", "rocks", "river", "road".
std::vector<std::string_view> sceneNames();
std::string_view sceneSummary(std::string_view name);  // "" for no such scene
std::optional<Scene> makeScene(std::string_view name);

}  // namespace wg::scene
