// The snow layer's patch grid (issue 5, §1; seed 2.3, 3.1): the seed's dimensions,
// the tangent frame snow_deformation's normal assumes, and following the camera by
// whole patches.
#include "runtime/snow/snow_patch_grid.hpp"

#include <gtest/gtest.h>

namespace wg::snow {
namespace {

TEST(SnowPatchGrid, DefaultIsTheSeedsEightByEightPatchesOf64Quads) {
  PatchGridSettings s;
  EXPECT_EQ(s.patches, 8);
  EXPECT_FLOAT_EQ(s.patchSize, 8.f);
  EXPECT_EQ(s.quadsPerPatch, 64);
  EXPECT_FLOAT_EQ(s.patchSize / float(s.quadsPerPatch), 0.125f);  // seed 5.2.1: 1.25 dm
}

TEST(SnowPatchGrid, MeshIsALevelGridWithTheLayersTangentFrame) {
  PatchGridSettings s{2, 4.f, 4};
  scene::Mesh m = patchGridMesh(s);
  EXPECT_EQ(m.positions.size(), 9u * 9u);
  EXPECT_EQ(m.indices.size(), 8u * 8u * 6u);
  for (std::size_t i = 0; i < m.positions.size(); ++i) {
    EXPECT_EQ(m.positions[i].y, 0.f);
    EXPECT_LE(std::abs(m.positions[i].x), 4.f);
    // Bitangent = cross(normal, tangent) * w must be +z (snow_deformation's .ywz).
    glm::vec3 b = glm::cross(m.normals[i], glm::vec3(m.tangents[i])) * m.tangents[i].w;
    EXPECT_NEAR(b.z, 1.f, 1e-6f);
  }
  // Every triangle faces up.
  for (std::size_t t = 0; t < m.indices.size(); t += 3) {
    glm::vec3 a = m.positions[m.indices[t]], b = m.positions[m.indices[t + 1]], c = m.positions[m.indices[t + 2]];
    EXPECT_GT(glm::cross(b - a, c - a).y, 0.f);
  }
}

TEST(SnowPatchGrid, FollowsTheCameraByWholePatches) {
  PatchGridSettings s;  // 8 patches of 8 m: the camera's patch sits just past the centre
  glm::vec3 o = patchGridOrigin(s, {3.f, 1.7f, -5.f}, 0.f);
  EXPECT_EQ(o, glm::vec3(0.f, 0.f, -8.f));
  // Within a patch the grid does not move at all.
  EXPECT_EQ(patchGridOrigin(s, {7.9f, 1.7f, -0.1f}, 0.f), o);
  // The camera is always at least half the grid minus one patch from its edge.
  for (float x = -20.f; x < 20.f; x += 0.7f) {
    glm::vec3 origin = patchGridOrigin(s, {x, 0.f, 0.f}, 0.f);
    EXPECT_GE(0.5f * s.extent() - std::abs(x - origin.x), 0.5f * s.extent() - s.patchSize);
  }
  EXPECT_EQ(wrappedPatches(s, {0.f, 0.f, 0.f}, {7.f, 0.f, 7.f}), 0);
  EXPECT_EQ(wrappedPatches(s, {0.f, 0.f, 0.f}, {8.5f, 0.f, 0.f}), 8);       // one column
  EXPECT_EQ(wrappedPatches(s, {0.f, 0.f, 0.f}, {8.5f, 0.f, 8.5f}), 15);     // a column and a row
  EXPECT_EQ(wrappedPatches(s, {0.f, 0.f, 0.f}, {500.f, 0.f, 0.f}), 64);     // all of them
}

}  // namespace
}  // namespace wg::snow
