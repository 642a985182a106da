// The CPU model of the deformation map: prints where the
// scripted paths put them, continuous trails at any speed, the snow-depth limit,
// refill at the configured rate, normals only where touched, and prints that survive
// recentring and a round trip out of the window.
#include "snow/deformation_map.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "snow/cpu_stamping.hpp"
#include "snow/deformation_texel.hpp"
#include "snow/snow_interactors.hpp"

namespace wg::snow {
namespace {

// 128² at 4 cm (5.12 m) in 16-texel tiles: small and fast, the same code as 1024².
const WindowSettings kSmall{128, 0.04f, 16};
const SnowCover kDeep{0.12f};  // shallower than a foot lifts: separate prints
constexpr double kFrame = 1.0 / 60.0;

Walker straightWalker(glm::vec2 from, glm::vec2 to, float speed) {
  Walker w;
  w.path = ScriptedPath({from, to}, speed);
  w.sink = 0.3f;
  return w;
}

// Runs a walker frame by frame from t0 to t1 into the map.
void walk(DeformationMap& map, const Walker& w, double t0, double t1, double frame, const SnowCover& cover) {
  for (double t = t0; t < t1; t += frame) {
    std::vector<Stamp> stamps;
    walkerStamps(w, t - frame, std::min(t, t1), cover, stamps);
    map.apply(stamps);
  }
}

TEST(DeformationMap, FootprintsLandWhereThePathPutsThem) {
  DeformationMap map(kSmall);
  Walker w = straightWalker({-2.f, -1.f}, {2.f, 1.f}, 1.4f);
  walk(map, w, 0.0, 4.0, kFrame, kDeep);
  float expected = std::min(w.sink, deepestPrint(kDeep));
  glm::vec2 heading = w.path.headingAt(0.f);
  for (int k = 0; k * w.stepLength <= w.path.length(); ++k) {
    glm::vec2 at = footfall(w, k);
    glm::vec2 heel = at - heading * (0.5f * w.foot.length - w.foot.heelRadius);
    EXPECT_NEAR(map.depthAt(heel), expected, 0.05f * expected) << "footfall " << k;
    // Between this footfall and the next, off both feet, the snow is untouched.
    glm::vec2 between = w.path.pointAt((float(k) + 0.5f) * w.stepLength);
    if ((k + 1) * w.stepLength <= w.path.length()) {
      EXPECT_EQ(map.depthAt(between), 0.f) << k;
    }
  }
  // Left and right feet alternate around the path.
  glm::vec2 left(-heading.y, heading.x);
  EXPECT_GT(glm::dot(footfall(w, 0) - w.path.pointAt(0.f), left), 0.f);
  EXPECT_LT(glm::dot(footfall(w, 1) - w.path.pointAt(w.stepLength), left), 0.f);
}

TEST(DeformationMap, AWalkerFasterThanOneStepPerFrameLeavesEveryPrint) {
  DeformationMap slow(kSmall), fast(kSmall);
  Walker w = straightWalker({-2.2f, 0.f}, {2.2f, 0.f}, 1.4f);
  walk(slow, w, 0.0, 4.0, kFrame, kDeep);
  // 40 m/s at 10 frames per second: five footfalls per frame.
  Walker sprinter = w;
  sprinter.path = ScriptedPath({{-2.2f, 0.f}, {2.2f, 0.f}}, 40.f);
  walk(fast, sprinter, 0.0, 1.0, 0.1, kDeep);
  int prints = 0;
  for (int k = 0; k * w.stepLength <= w.path.length(); ++k, ++prints)
    EXPECT_GT(fast.depthAt(footfall(w, k)), 0.f) << "footfall " << k << " missing";
  EXPECT_GE(prints, 5);
  // Same prints, whatever the frame rate.
  auto a = slow.texels().heights, b = fast.texels().heights;
  EXPECT_TRUE(std::equal(a.begin(), a.end(), b.begin()));
}

TEST(DeformationMap, DeepSnowJoinsTheFootprintsIntoAFurrow) {
  DeformationMap map(kSmall);
  Walker w = straightWalker({-2.f, 0.f}, {2.f, 0.f}, 1.4f);
  SnowCover deep{0.4f};  // deeper than the feet lift
  walk(map, w, 0.0, 4.0, kFrame, deep);
  // Along the left foot's line, from its first to its last print, no gap.
  float y = 0.5f * w.footSpacing;
  for (float x = -2.f; x <= -2.f + 4.f * w.stepLength; x += kSmall.texelSize)
    EXPECT_GT(map.depthAt({x, y}), 0.f) << x;
}

TEST(DeformationMap, FastVehicleRutsHaveNoGaps) {
  DeformationMap map(kSmall);
  Vehicle v;
  v.path = ScriptedPath({{-2.2f, -0.5f}, {2.2f, -0.5f}}, 30.f);  // 30 m/s: half a metre a frame
  for (double t = 0.0; t < 0.2; t += kFrame) {
    std::vector<Stamp> stamps;
    vehicleStamps(v, t, t + kFrame, kDeep, stamps);
    map.apply(stamps);
  }
  float rutDepth = std::min(v.sink, deepestPrint(kDeep));
  for (float x = -2.2f; x <= 2.2f; x += kSmall.texelSize) {
    EXPECT_NEAR(map.depthAt({x, -0.5f + 0.5f * v.track}), rutDepth, 2e-3f) << x;
    EXPECT_NEAR(map.depthAt({x, -0.5f - 0.5f * v.track}), rutDepth, 2e-3f) << x;
    EXPECT_EQ(map.depthAt({x, -0.5f}), 0.f) << "between the ruts at " << x;
  }
}

TEST(DeformationMap, ZeroSnowDepthLeavesNoDeformation) {
  DeformationMap map(kSmall);
  Walker w = straightWalker({-2.f, 0.f}, {2.f, 0.f}, 1.4f);
  walk(map, w, 0.0, 4.0, kFrame, SnowCover{0.f});
  Vehicle v;
  v.path = ScriptedPath({{-2.f, 1.f}, {2.f, 1.f}}, 5.f);
  std::vector<Stamp> stamps;
  vehicleStamps(v, 0.0, 1.0, SnowCover{0.f}, stamps);
  map.apply(stamps);
  auto h = map.texels().heights, n = map.texels().normals;
  EXPECT_TRUE(std::all_of(h.begin(), h.end(), [](auto t) { return t == 0u; }));
  EXPECT_TRUE(std::all_of(n.begin(), n.end(), [](auto t) { return t == 0u; }));
}

TEST(DeformationMap, StampOrderDoesNotMatter) {
  DeformationMap forward(kSmall), backward(kSmall);
  std::vector<Stamp> stamps;
  Walker w = straightWalker({-2.f, 0.f}, {2.f, 0.3f}, 1.4f);
  walkerStamps(w, -1.0, 3.0, kDeep, stamps);
  Vehicle v;
  v.path = ScriptedPath({{-2.f, -0.4f}, {2.f, 0.6f}}, 2.f);
  vehicleStamps(v, 0.0, 2.0, kDeep, stamps);
  forward.apply(stamps);
  std::reverse(stamps.begin(), stamps.end());
  backward.apply(stamps);
  auto a = forward.texels(), b = backward.texels();
  EXPECT_TRUE(std::equal(a.heights.begin(), a.heights.end(), b.heights.begin()));
  EXPECT_TRUE(std::equal(a.normals.begin(), a.normals.end(), b.normals.begin()));
}

TEST(DeformationMap, NormalsChangeOnlyAroundStampsAndTiltIntoThePrint) {
  DeformationMap map(kSmall);
  Stamp s = capsule({0.f, 0.f}, {0.f, 0.f}, 0.3f, kDeep, 0.1f);
  map.apply(std::span(&s, 1));
  TexelRect touched = stampBounds(s, map.window()).grown(1);
  int changed = 0;
  for (int z = map.window().origin().y; z < map.window().origin().y + 128; ++z)
    for (int x = map.window().origin().x; x < map.window().origin().x + 128; ++x) {
      bool flat = map.texels().normals[map.window().storageIndex({x, z})] == 0u;
      if (!touched.contains({x, z})) {
        EXPECT_TRUE(flat) << x << "," << z;
      }
      changed += !flat;
    }
  EXPECT_GT(changed, 0);
  // On the wall east of the centre the surface faces back west, into the print.
  glm::vec3 wall = map.normalAt({0.3f - 0.04f, 0.f});
  EXPECT_LT(wall.x, -0.1f);
  EXPECT_NEAR(map.normalAt({0.f, 0.f}).y, 1.f, 1e-3f);  // flat bottom
}

TEST(DeformationMap, RefillReducesPrintDepthAtTheConfiguredRate) {
  // Refill reaches every tile of the 8 x 8 each call, so the rate is exact at every call.
  DeformationMap map(WindowSettings{128, 0.04f, 16, kSmall.printStoreBudget, 64});
  Stamp s = capsule({0.f, 0.f}, {0.f, 0.f}, 0.3f, SnowCover{0.3f}, 0.1f);
  map.apply(std::span(&s, 1));
  ASSERT_NEAR(map.depthAt({0.f, 0.f}), 0.1f, kDepthQuantum);
  const double rate = 0.02 / 3600.0;  // 2 cm per hour
  for (int minute = 0; minute < 90; ++minute) map.refill(rate, 60.0);
  // 1.5 h at 2 cm/h: 3 cm filled, to within one quantum of accumulation.
  EXPECT_NEAR(map.depthAt({0.f, 0.f}), 0.07f, 1.5f * kDepthQuantum);
  for (int minute = 0; minute < 600; ++minute) map.refill(rate, 60.0);
  EXPECT_EQ(map.depthAt({0.f, 0.f}), 0.f);  // filled up, never raised above the snow
  EXPECT_EQ(map.heightAt({0.f, 0.f}), 0.f);
}

TEST(DeformationMap, PrintsSurviveRecentringAndARoundTripOutOfTheWindow) {
  DeformationMap map(kSmall);
  Walker w = straightWalker({-2.f, -1.f}, {2.f, 1.f}, 1.4f);
  walk(map, w, 0.0, 4.0, kFrame, kDeep);
  std::vector<float> before;
  for (int k = 0; k * w.stepLength <= w.path.length(); ++k) before.push_back(map.depthAt(footfall(w, k)));
  std::vector<std::uint32_t> snapshot(map.texels().heights.begin(), map.texels().heights.end());

  // Small moves: the window slides by tiles, and the prints that stay do not move.
  Recentring step = map.follow({1.f, 0.f});
  EXPECT_TRUE(step.moved());
  for (int k = 0; k * w.stepLength <= w.path.length(); ++k) {
    glm::vec2 at = footfall(w, k);
    if (map.window().contains(map.window().texelAt(at))) {
      EXPECT_EQ(map.depthAt(at), before[k]) << k;
    }
  }
  // Away: everything leaves the window, deformed tiles go to the store.
  for (float x = 1.f; x <= 60.f; x += 0.7f) map.follow({x, 0.f});
  EXPECT_GT(map.store().tileCount(), 0u);
  for (int k = 0; k * w.stepLength <= w.path.length(); ++k) EXPECT_EQ(map.depthAt(footfall(w, k)), 0.f);
  // And back: every print returns exactly.
  for (float x = 60.f; x >= 0.f; x -= 0.7f) map.follow({x, 0.f});
  map.follow({0.f, 0.f});
  EXPECT_EQ(map.store().tileCount(), 0u);
  for (int k = 0; k * w.stepLength <= w.path.length(); ++k) EXPECT_EQ(map.depthAt(footfall(w, k)), before[k]) << k;
  auto now = map.texels().heights;
  EXPECT_TRUE(std::equal(now.begin(), now.end(), snapshot.begin()));
}

TEST(DeformationMap, RecentringTouchesOnlyTheTilesThatLeaveAndEnter) {
  DeformationMap map(kSmall);
  std::vector<Stamp> stamps;
  for (float x = -2.4f; x < 2.4f; x += 0.3f)
    for (float z = -2.4f; z < 2.4f; z += 0.3f) stamps.push_back(capsule({x, z}, {x, z}, 0.05f, kDeep, 0.1f));
  map.apply(stamps);
  std::vector<std::uint32_t> before(map.texels().heights.begin(), map.texels().heights.end());
  TexelRect old = map.window().rect();
  // One tile east: one column of tiles leaves (west) and one enters (east).
  Recentring r = map.follow({kSmall.texelSize * float(kSmall.tileTexels) + 0.01f, 0.f});
  const int tilesPerSide = int(kSmall.resolution / kSmall.tileTexels);
  EXPECT_EQ(r.evicted, std::size_t(tilesPerSide));
  TexelRect stays = old.intersect(map.window().rect());
  EXPECT_EQ(stays.size.x, old.size.x - int(kSmall.tileTexels));
  for (int z = stays.min.y; z < stays.min.y + stays.size.y; ++z)
    for (int x = stays.min.x; x < stays.min.x + stays.size.x; ++x) {
      std::size_t i = map.window().storageIndex({x, z});
      ASSERT_EQ(map.texels().heights[i], before[i]) << "texel " << x << "," << z << " stayed but changed";
    }
}

TEST(DeformationMap, StoredPrintsCatchUpOnTheRefillTheyMissed) {
  DeformationMap map(kSmall);
  Stamp s = capsule({0.f, 0.f}, {0.f, 0.f}, 0.3f, SnowCover{0.3f}, 0.1f);
  map.apply(std::span(&s, 1));
  map.follow({50.f, 0.f});  // one jump: the print is stored
  ASSERT_EQ(map.store().tileCount(), 4u);  // a 0.6 m disc (plus rim) spans 2x2 tiles at the origin
  map.refill(0.01 / 3600.0, 3600.0);  // 1 cm
  map.follow({0.f, 0.f});
  EXPECT_NEAR(map.depthAt({0.f, 0.f}), 0.09f, 1.5f * kDepthQuantum);
}

TEST(PrintTileStore, OnlyDeformedTilesAreKeptAndCounted) {
  DeformationMap map(kSmall);
  map.follow({100.f, 100.f});
  EXPECT_EQ(map.store().tileCount(), 0u);  // nothing deformed, nothing stored
  EXPECT_EQ(map.store().memoryBytes(), 0u);
  Stamp s = capsule({100.f, 100.f}, {100.f, 100.f}, 0.1f, kDeep, 0.1f);
  map.apply(std::span(&s, 1));
  map.follow({0.f, 0.f});
  EXPECT_GE(map.store().tileCount(), 1u);
  // Sparse: a 0.2 m disc keeps a few dozen texels per tile, not all 256.
  int deformedTexels = 0;
  for (int z = -5; z <= 5; ++z)
    for (int x = -5; x <= 5; ++x) {
      StampProfile p = stampProfile(s, glm::vec2(100.f) + (glm::vec2(x, z) + 0.5f) * kSmall.texelSize);
      deformedTexels += packTexel(p.depth, p.rim) != 0;
    }
  std::size_t payload = deformedTexels * (sizeof(std::uint16_t) + sizeof(std::uint32_t));
  EXPECT_GE(map.store().memoryBytes(), payload);
  EXPECT_LT(map.store().memoryBytes(), map.store().tileCount() * 16u * 16u * sizeof(std::uint32_t));
  EXPECT_EQ(map.mapBytes(), 2u * 128u * 128u * sizeof(std::uint32_t));
}

}  // namespace
}  // namespace wg::snow
