#include "host/scene/preview_stand.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include "host/scene/probe_visibility.hpp"
#include "host/scene/shapes.hpp"
#include "host/scene/stage.hpp"

namespace wg::scene {

namespace {
constexpr const char* kGroundGraph = "terrain";
constexpr const char* kFurnitureGraph = "rock";  // the roof and the posts

// Layout on the ground (y = 0), in metres: the camera "front" looks towards -z, the sun
// comes from the front right. The sphere and the ramp stand in front, the rock and the
// cube behind the gaps between them. Shapes are a metre or two across, so texture scales and
// eq. 3.10's snow depth (0.25 m by default) read as they do in the scenes.
constexpr float kSphereRadius = 1.f;
constexpr glm::vec2 kSphereAt{-1.8f, 1.2f};
constexpr float kRockRadius = 1.2f;
constexpr std::uint32_t kRockSeed = 7u;
constexpr int kRockDetail = 4;
constexpr float kRockBedding = 0.1f;  // sunk this far into the ground
constexpr glm::vec2 kRockAt{0.f, -1.4f};
constexpr glm::vec3 kRampSize{2.f, 2.f, 2.f};  // as tall as deep: 45 degrees
constexpr float kRampBevel = 0.06f;
constexpr glm::vec2 kRampAt{1.6f, 1.2f};
// Turned so the front camera sees a side and the slope, and the slope faces the sun.
constexpr float kRampYawDegrees = 60.f;
constexpr float kCubeSize = 1.4f;
constexpr float kCubeBevel = 0.06f;
constexpr float kPostWidth = 0.3f, kPostHeight = 1.6f;
constexpr glm::vec2 kCubeAt{3.9f, -1.4f};
// Turned so the front camera sees a diamond-shaped side (the cube stands on an edge).
constexpr float kCubeYawDegrees = -35.f;
// The roof: on the left, level with the sphere, so no camera looks through it at the
// shapes; high enough to look under.
constexpr glm::vec3 kRoofCentre{-4.6f, 0.f, 1.2f};
constexpr glm::vec2 kRoofSize{3.6f, 3.6f};
constexpr float kRoofHeight = 2.6f;  // the underside, above the ground
constexpr float kRoofThickness = 0.2f;
constexpr float kRoofBevel = 0.08f;
constexpr float kRoofPostWidth = 0.2f;
constexpr glm::vec3 kOpenGroundProbe{0.f, 0.f, 3.f};

glm::mat4 at(glm::vec3 position) { return glm::translate(glm::mat4(1.f), position); }
glm::mat4 turned(glm::mat4 model, float degrees, glm::vec3 axis) { return glm::rotate(model, glm::radians(degrees), axis); }
constexpr glm::vec3 kXAxis{1.f, 0.f, 0.f}, kYAxis{0.f, 1.f, 0.f};

SceneObject shape(std::string name, const std::string& graph, Mesh mesh, glm::mat4 model) {
  return {std::move(name), graph, std::move(mesh), model};
}

// The cube stands on one edge, tilted 45 degrees: its upper faces slope up, its lower
// faces overhang, its sides are vertical. The shapes' edges are rounded: eq. 3.10's
// snow moves vertices along their normals and would lift hard-edged faces apart.
std::vector<SceneObject> cubeOnPost(const std::string& graph) {
  float halfDiagonal = 0.5f * kCubeSize * glm::root_two<float>();
  glm::mat4 model = turned(turned(at({kCubeAt.x, kPostHeight + halfDiagonal, kCubeAt.y}), kCubeYawDegrees, kYAxis), 45.f, kXAxis);
  glm::vec3 half(0.5f * kCubeSize);
  glm::vec3 postMin(kCubeAt.x - 0.5f * kPostWidth, 0.f, kCubeAt.y - 0.5f * kPostWidth);
  glm::vec3 postMax(kCubeAt.x + 0.5f * kPostWidth, kPostHeight, kCubeAt.y + 0.5f * kPostWidth);
  return {shape("cube", graph, roundedBox(-half, half, kCubeBevel), model), shape("post", kFurnitureGraph, box(postMin, postMax), glm::mat4(1.f))};
}

// A slab on four posts. Rounded edges: snow on the slab thickens it instead of lifting
// its top off the sides.
Mesh roof() {
  glm::vec3 half(0.5f * kRoofSize.x, 0.5f * kRoofThickness, 0.5f * kRoofSize.y);
  glm::vec3 slabCentre = kRoofCentre + glm::vec3(0.f, kRoofHeight + half.y, 0.f);
  Mesh m = roundedBox(slabCentre - half, slabCentre + half, kRoofBevel);
  for (glm::vec2 p : shelterPostPositions(kRoofCentre, kRoofSize)) {
    glm::vec3 postHalf(0.5f * kRoofPostWidth, 0.f, 0.5f * kRoofPostWidth);
    append(m, box(glm::vec3(p.x, 0.f, p.y) - postHalf, glm::vec3(p.x, kRoofHeight, p.y) + postHalf));
  }
  return m;
}

std::vector<SceneObject> standObjects(const std::string& graph) {
  Mesh boulder = rock(kRockSeed, kRockRadius, kRockDetail);
  float rockY = -kRockBedding - bounds(boulder).min.y;
  std::vector<SceneObject> objects = {
      shape("sphere", graph, sphere(kSphereRadius), at({kSphereAt.x, kSphereRadius, kSphereAt.y})),
      shape("rock", graph, std::move(boulder), at({kRockAt.x, rockY, kRockAt.y})),
      shape("ramp", graph, ramp(kRampSize, kRampBevel), turned(at({kRampAt.x, 0.f, kRampAt.y}), kRampYawDegrees, kYAxis)),
  };
  for (auto& o : cubeOnPost(graph)) objects.push_back(std::move(o));
  objects.push_back(shape("roof", kFurnitureGraph, roof(), glm::mat4(1.f)));
  return objects;
}
}  // namespace

std::vector<std::string_view> previewStandSubjects() { return {"sphere", "rock", "ramp", "cube"}; }

Scene previewStand(const std::string& graph, std::string name) {
  StageOptions options;
  options.groundGraph = kGroundGraph;
  options.groundHeight = 0.f;
  Scene scene = stageAround(std::move(name), standObjects(graph), options);
  scene.probes.push_back({"under-roof", kRoofCentre, {0.f, 1.f, 0.f}, "sheltered", "ground", {}});
  scene.probes.push_back({"open-ground", kOpenGroundProbe, {0.f, 1.f, 0.f}, "open", "ground", {}});
  markProbeVisibility(scene, worldMeshes(scene));
  return scene;
}

}  // namespace wg::scene
