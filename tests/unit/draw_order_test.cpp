// What the runtime does for blended and two-UV-set meshes without a GPU: the colour
// pass's draw order, object centres, and the second texture coordinate set through
// mesh appends.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "host/draw_order.hpp"

namespace wg {
namespace {

TEST(DrawOrder, OpaqueInSceneOrderThenBlendedFarthestFirst) {
  const glm::vec3 eye(0.f);
  const std::vector<DrawCandidate> objects = {
      {true, {0.f, 0.f, -2.f}},  // near glass
      {false, {}},               // ground
      {true, {0.f, 0.f, -9.f}},  // far glass
      {false, {}},               // rock
      {true, {5.f, 0.f, 0.f}},   // middle glass
      {true, {0.f, 5.f, 0.f}},   // as far as the middle one: keeps its scene order after it
  };
  EXPECT_EQ(colourDrawOrder(objects, eye), (std::vector<std::size_t>{1, 3, 2, 4, 5, 0}));
  EXPECT_EQ(colourDrawOrder({}, eye), std::vector<std::size_t>{});
}

TEST(DrawOrder, CentreIsTheMiddleOfTheTransformedBounds) {
  scene::Mesh mesh;
  scene::addVertex(mesh, {0.f, 0.f, 0.f}, {0.f, 1.f, 0.f}, {0.f, 0.f});
  scene::addVertex(mesh, {2.f, 4.f, 6.f}, {0.f, 1.f, 0.f}, {1.f, 1.f});
  EXPECT_EQ(worldCentre(mesh, glm::mat4(1.f)), glm::vec3(1.f, 2.f, 3.f));
  EXPECT_EQ(worldCentre(mesh, glm::translate(glm::mat4(1.f), glm::vec3(10.f, 0.f, 0.f))), glm::vec3(11.f, 2.f, 3.f));
  EXPECT_EQ(worldCentre(scene::Mesh{}, glm::translate(glm::mat4(1.f), glm::vec3(1.f, 2.f, 3.f))), glm::vec3(1.f, 2.f, 3.f));
}

scene::Mesh oneVertex(glm::vec2 uv0) {
  scene::Mesh mesh;
  scene::addVertex(mesh, {0.f, 0.f, 0.f}, {0.f, 1.f, 0.f}, uv0);
  return mesh;
}

TEST(DrawOrder, AppendKeepsTheSecondSetParallelToThePositions) {
  scene::Mesh withSet = oneVertex({0.1f, 0.2f});
  withSet.texcoords1 = {{0.7f, 0.8f}};
  scene::Mesh plain = oneVertex({0.3f, 0.4f});

  scene::Mesh merged;
  scene::append(merged, plain);
  EXPECT_TRUE(merged.texcoords1.empty());  // nobody has a second set: none is made
  scene::append(merged, withSet);
  scene::append(merged, plain);
  // Set 0 stands in where a mesh has no second set.
  EXPECT_EQ(merged.texcoords1, (std::vector<glm::vec2>{{0.3f, 0.4f}, {0.7f, 0.8f}, {0.3f, 0.4f}}));
  EXPECT_EQ(merged.texcoords1.size(), merged.positions.size());
}

}  // namespace
}  // namespace wg
