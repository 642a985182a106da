// The snow layer's patch grid (seed 2.3, 3.1): the seed's dimensions, a
// fine square on the print map's texels around the camera, the tangent frame
// snow_deformation's normal assumes, and following the camera by whole steps.
#include "host/snowfield/snow_patch_grid.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>

namespace wg::snow {
namespace {

TEST(SnowPatchGrid, DefaultIsTheSeedsEightByEightPatchesOf64Quads) {
  PatchGridSettings s;
  EXPECT_EQ(s.patches, 8);
  EXPECT_FLOAT_EQ(s.patchSize, 8.f);
  EXPECT_EQ(s.quadsPerPatch, 64);
  EXPECT_FLOAT_EQ(s.spacing(), 0.125f);  // seed 5.2.1: 1.25 dm
}

// Prints are 9-11 cm wide: around the camera a vertex stands on every 4 cm texel.
TEST(SnowPatchGrid, FineSquareAroundTheCameraHasOneVertexPerPrintTexel) {
  PatchGridSettings s;
  std::vector<float> lines = patchGridLines(s);
  ASSERT_TRUE(std::is_sorted(lines.begin(), lines.end()));
  EXPECT_FLOAT_EQ(lines.front(), -32.f);
  EXPECT_FLOAT_EQ(lines.back(), 32.f);
  int fine = 0, coarse = 0;
  for (std::size_t i = 1; i < lines.size(); ++i) {
    float gap = lines[i] - lines[i - 1], mid = 0.5f * (lines[i] + lines[i - 1]);
    if (std::abs(mid) < s.fineHalfWidth) {
      EXPECT_NEAR(gap, 0.04f, 1e-4f) << mid;
      ++fine;
    } else {
      EXPECT_NEAR(gap, 0.125f, 1e-4f) << mid;
      ++coarse;
    }
  }
  EXPECT_EQ(fine, 400);    // 16 m of 4 cm
  EXPECT_EQ(coarse, 384);  // 2 x 24 m of 12.5 cm
  // No fine square: the seed's grid.
  s.fineHalfWidth = 0.f;
  EXPECT_EQ(patchGridLines(s).size(), 513u);
  // A fine square that is not a whole number of quads would leave a crack.
  s.fineHalfWidth = 6.02f;
  EXPECT_THROW(patchGridLines(s), std::invalid_argument);
}

TEST(SnowPatchGrid, MeshIsALevelGridWithTheLayersTangentFrame) {
  PatchGridSettings s{2, 4.f, 4, 1.f, 0.5f, 1.f};
  scene::Mesh m = patchGridMesh(s);
  // 8 m: 3 coarse quads of 1 m, 4 fine of 0.5 m, 3 coarse: 10 quads, 11 lines a side.
  EXPECT_EQ(m.positions.size(), 11u * 11u);
  EXPECT_EQ(m.indices.size(), 10u * 10u * 6u);
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

TEST(SnowPatchGrid, FollowsTheCameraByWholeStepsOntoFormerVertices) {
  PatchGridSettings s;
  EXPECT_EQ(patchGridOrigin(s, {3.2f, 1.7f, -5.7f}, 0.f), glm::vec3(3.f, 0.f, -6.f));
  // The camera is never more than half a step from the fine square's centre.
  for (float x = -20.f; x < 20.f; x += 0.07f)
    EXPECT_LE(std::abs(x - patchGridOrigin(s, {x, 0.f, 0.f}, 0.f).x), 0.5f * s.followStep + 1e-5f);
  // Wherever the grid stands, every fine vertex is on a texel corner and every coarse
  // vertex on the seed's 12.5 cm lattice, so nothing the vertex stage samples swims as
  // the camera moves.
  auto onLattice = [](float x, float spacing) { return std::abs(x / spacing - std::round(x / spacing)) < 1e-2f; };
  EXPECT_TRUE(onLattice(s.followStep, s.fineSpacing));
  EXPECT_TRUE(onLattice(s.followStep, s.spacing()));
  for (float line : patchGridLines(s)) {
    bool fine = std::abs(line) < s.fineHalfWidth;
    EXPECT_TRUE(onLattice(line, fine ? s.fineSpacing : s.spacing())) << line;
  }
  EXPECT_EQ(wrappedPatches(s, {0.f, 0.f, 0.f}, {7.f, 0.f, 7.f}), 0);
  EXPECT_EQ(wrappedPatches(s, {0.f, 0.f, 0.f}, {8.5f, 0.f, 0.f}), 8);       // one column
  EXPECT_EQ(wrappedPatches(s, {0.f, 0.f, 0.f}, {8.5f, 0.f, 8.5f}), 15);     // a column and a row
  EXPECT_EQ(wrappedPatches(s, {0.f, 0.f, 0.f}, {500.f, 0.f, 0.f}), 64);     // all of them
}

}  // namespace
}  // namespace wg::snow
