// A frame's snow work stays within its budget (WindowSettings::workPerFrame): stamps
// beyond it wait and catch up to the same map, and recentring moves only the tiles
// near prints, leaving flat snow with straight-up normals wherever it skipped.
// On lavapipe with the validation layers on.
#include <gtest/gtest.h>

#include <algorithm>

#include "snow/deformation_texel.hpp"
#include "snow/gpu_deformation_map.hpp"
#include "snow/snow_interactors.hpp"
#include "tests/snow/snow_gpu_support.hpp"

namespace wg::snow {
namespace {

using testing::snowContext;
using FrameBudget = testing::ValidatedGpuTest;

const SnowCover kCover{0.12f};
constexpr double kFrame = 1.0 / 60.0;

WindowSettings budgeted(std::uint32_t work) {
  WindowSettings s{128, 0.04f, 16};
  s.workPerFrame = work;
  return s;
}

// Footprints of a walker crossing the window: many more than one frame's budget.
std::vector<Stamp> walk(std::size_t most) {
  Walker w;
  w.path = ScriptedPath({{-2.2f, -2.f}, {2.2f, 2.f}}, 1.4f);
  Vehicle v;
  v.path = ScriptedPath({{-2.2f, 1.f}, {2.2f, -1.f}}, 1.4f);
  std::vector<Stamp> stamps;
  for (double t = 0.0; t < 5.0 && stamps.size() < most; t += kFrame) {
    walkerStamps(w, t - kFrame, t, kCover, stamps);
    vehicleStamps(v, t - kFrame, t, kCover, stamps);
  }
  stamps.resize(std::min(stamps.size(), most));
  return stamps;
}

TEST_F(FrameBudget, QueuedStampsCatchUpWithinTheBudgetToTheSameMap) {
  const std::uint32_t budget = 2048;
  GpuDeformationMap framed(*snowContext(), budgeted(budget)), atOnce(*snowContext(), budgeted(budget));
  std::vector<Stamp> stamps = walk(200);
  ASSERT_EQ(stamps.size(), 200u);
  atOnce.apply(stamps);
  std::uint64_t before = framed.invocations();
  framed.frame({.stamps = stamps});
  int frames = 1;
  for (; framed.queuedStamps() != 0 && frames < 1000; ++frames) {
    EXPECT_LE(framed.invocations() - before, budget) << "frame " << frames;
    before = framed.invocations();
    framed.frame({});
  }
  EXPECT_LE(framed.invocations() - before, budget);
  EXPECT_GT(frames, 10) << "200 stamps do not fit a few frames of 2048 invocations";
  EXPECT_EQ(framed.queuedStamps(), 0u);
  // atomicMax merges in any order: the same heights, and so the same normals.
  auto a = framed.texels(), b = atOnce.texels();
  EXPECT_TRUE(std::equal(a.heights.begin(), a.heights.end(), b.heights.begin()));
  EXPECT_TRUE(std::equal(a.normals.begin(), a.normals.end(), b.normals.begin()));
}

TEST_F(FrameBudget, AQueueOfMoreThanASecondIsPressedAtOnce) {
  GpuDeformationMap framed(*snowContext(), budgeted(256));
  framed.frame({.stamps = walk(400)});
  EXPECT_EQ(framed.queuedStamps(), 0u);
}

// A scene that stamps more than a budget every frame still fills its prints in: a tile
// owed refill keeps a tile's share of each frame from the stamps.
TEST_F(FrameBudget, RefillGoesOnWhileStampsFillEveryBudget) {
  GpuDeformationMap framed(*snowContext(), budgeted(2048));
  Stamp print = capsule({-1.f, -1.f}, {-1.f, -1.f}, 0.2f, kCover, kCover.depth);
  framed.frame({.stamps = std::span(&print, 1)});
  const float before = framed.depthAt({-1.f, -1.f});
  // 10 cm an hour over a minute of frames: 1.7 mm, 17 quanta.
  std::vector<Stamp> busy(8, capsule({1.f, 1.f}, {1.4f, 1.f}, 0.3f, kCover, 0.05f));
  for (int f = 0; f < 60; ++f)
    framed.frame({.stamps = busy, .refillMetresPerSecond = 0.1 / 3600.0, .seconds = 1.0});
  EXPECT_GT(framed.queuedStamps(), 0u) << "the stamps fill every frame's budget";
  EXPECT_LT(framed.depthAt({-1.f, -1.f}), before - 0.001f);
}

// A window move transfers nothing when no tile near it holds a print.
TEST_F(FrameBudget, RecentringUntouchedSnowMovesNoTiles) {
  GpuDeformationMap framed(*snowContext(), budgeted(8192));
  const int start = framed.window().origin().x;
  std::uint64_t before = framed.invocations();
  for (float x = 0.f; x <= 3.f; x += 0.05f) framed.frame({.camera = {x, 0.f}});
  EXPECT_GE(framed.window().origin().x, start + 64) << "four tiles east";
  EXPECT_EQ(framed.invocations(), before);
}

// A print right at a tile's edge tilts the normals of the neighbouring tile's first
// column, though that tile holds no print. When the neighbour leaves the window, the
// fresh tile entering its slot must not inherit those normals.
TEST_F(FrameBudget, AFreshTileNeverInheritsTheNormalsOfItsSlot) {
  GpuDeformationMap framed(*snowContext(), budgeted(8192));
  const SnowWindow& w = framed.window();
  const int n = w.tileTexels();
  // The first tile column (x from origin to origin + n) leaves when the window moves
  // one tile east; press a print whose box starts exactly at the second column.
  const int edge = w.origin().x + n;
  Stamp print{};
  for (float x = w.texelCentre({edge, 0}).x; x < w.texelCentre({edge + 10, 0}).x; x += 0.002f) {
    print = capsule({x, 0.f}, {x, 0.f}, 0.1f, kCover, kCover.depth);
    if (stampBounds(print, w).min.x == edge) break;
  }
  ASSERT_EQ(stampBounds(print, w).min.x, edge);
  framed.frame({.stamps = std::span(&print, 1)});
  auto tilted = framed.texels();
  ASSERT_NE(tilted.normals[w.storageIndex({edge - 1, w.texelAt({0.f, 0.f}).y})], 0u)
      << "the first column's edge texel leans towards the print";
  // Walk east by one tile: the first column leaves, a fresh column enters its slots.
  const int slotColumn = edge - n;
  glm::vec2 camera(0.f);
  while (framed.window().origin().x <= slotColumn) {
    camera.x += 0.05f;
    framed.frame({.camera = camera});
  }
  framed.frame({.camera = camera});  // the move's normals, deferred to the next frames
  framed.frame({.camera = camera});
  auto moved = framed.texels();
  const SnowWindow& after = framed.window();
  int leaning = 0;
  for (int z = after.origin().y; z < after.origin().y + int(after.resolution()); ++z)
    for (int x = 0; x < n; ++x) {
      std::size_t slot = after.storageIndex({after.origin().x + int(after.resolution()) - n + x, z});
      leaning += moved.normals[slot] != 0u || moved.heights[slot] != 0u;
    }
  EXPECT_EQ(leaning, 0) << "texels of the entered column that are not flat snow";
}

}  // namespace
}  // namespace wg::snow
