// Prints made outside the window go to the print store and appear, texel for texel,
// when the window reaches them: far away, across the window's edge, and after the
// refill they missed.
#include "snow/beyond_window_stamping.hpp"

#include <gtest/gtest.h>

#include <limits>

#include "snow/deformation_map.hpp"
#include "snow/deformation_texel.hpp"
#include "snow/snow_interactors.hpp"

namespace wg::snow {
namespace {

const WindowSettings kSmall{128, 0.04f, 16};
const SnowCover kCover{0.12f};
constexpr double kFrame = 1.0 / 60.0;
const glm::vec2 kFar{60.f, -35.f};

std::vector<Stamp> walkerTrail(glm::vec2 from, glm::vec2 to) {
  Walker w;
  w.path = ScriptedPath({from, to}, 1.4f);
  std::vector<Stamp> stamps;
  for (double t = 0.0; t < 3.0; t += kFrame) walkerStamps(w, t - kFrame, t, kCover, stamps);
  return stamps;
}

// The heights of the window, in world order, around `centre`.
std::vector<std::uint32_t> windowAround(DeformationMap& map, glm::vec2 centre) {
  map.follow(centre);
  std::vector<std::uint32_t> out;
  TexelRect r = map.window().rect();
  for (int z = r.min.y; z < r.min.y + r.size.y; ++z)
    for (int x = r.min.x; x < r.min.x + r.size.x; ++x)
      out.push_back(map.texels().heights[map.window().storageIndex({x, z})]);
  return out;
}

TEST(BeyondWindow, PrintsMadeFarAwayAppearWhenTheWindowArrives) {
  std::vector<Stamp> trail = walkerTrail(kFar - glm::vec2(1.5f, 0.f), kFar + glm::vec2(1.5f, 0.5f));
  DeformationMap here(kSmall);  // the window stays at the origin while the walker is far away
  here.apply(trail);
  EXPECT_GT(here.store().tileCount(), 0u);
  DeformationMap there(kSmall, kFar);  // the same walk seen from inside the window
  there.apply(trail);
  EXPECT_EQ(there.store().tileCount(), 0u);
  std::vector<std::uint32_t> restored = windowAround(here, kFar), direct = windowAround(there, kFar);
  EXPECT_EQ(restored, direct);
  EXPECT_GT(here.depthAt(kFar - glm::vec2(1.5f, 0.f) + glm::vec2(0.f, 0.09f)), 0.f);
  EXPECT_EQ(here.store().tileCount(), 0u) << "every tile came back";
}

TEST(BeyondWindow, AStampAcrossTheEdgeIsSplitBetweenMapAndStore) {
  DeformationMap map(kSmall);
  float edge = map.window().texelCentre(map.window().rect().min + map.window().rect().size).x;
  Stamp rut = capsule({edge - 1.f, 0.f}, {edge + 1.f, 0.f}, 0.1f, kCover, 0.1f);
  map.apply(std::span(&rut, 1));
  EXPECT_GT(map.depthAt({edge - 0.5f, 0.f}), 0.f);
  EXPECT_GT(map.store().tileCount(), 0u);
  DeformationMap whole(kSmall, {edge, 0.f});
  whole.apply(std::span(&rut, 1));
  map.follow({edge, 0.f});
  for (float x = edge - 1.f; x <= edge + 1.f; x += kSmall.texelSize)
    EXPECT_EQ(map.depthAt({x, 0.f}), whole.depthAt({x, 0.f})) << x - edge;
}

TEST(BeyondWindow, PrintsMadeAwayCatchUpOnRefillAndMergeWithStoredOnes) {
  DeformationMap map(kSmall);
  Stamp first = capsule(kFar, kFar, 0.2f, SnowCover{0.3f}, 0.1f);
  map.apply(std::span(&first, 1));
  map.refill(0.01 / 3600.0, 3600.0);  // 1 cm while nobody looks
  // A shallower print overlapping the first, made after the refill.
  Stamp second = capsule(kFar + glm::vec2(0.3f, 0.f), kFar + glm::vec2(0.3f, 0.f), 0.2f, SnowCover{0.3f}, 0.05f);
  map.apply(std::span(&second, 1));
  map.refill(0.01 / 3600.0, 3600.0);  // another centimetre
  map.follow(kFar);
  EXPECT_NEAR(map.depthAt(kFar), 0.08f, 1.5f * kDepthQuantum);
  EXPECT_NEAR(map.depthAt(kFar + glm::vec2(0.3f, 0.f)), 0.04f, 1.5f * kDepthQuantum);
}

TEST(BeyondWindow, ALongDiagonalJumpWritesOnlyTheTilesItCrosses) {
  SnowWindow window(kSmall);
  PrintTileStore store;
  // 280 m in one frame: its bounding box holds ~96,000 tiles of 0.64 m, its path ~1,300.
  Stamp jump = capsule({100.f, 100.f}, {300.f, 300.f}, 0.1f, kCover, 0.1f);
  std::size_t written = stampBeyondWindow(window, std::span(&jump, 1), store, 0);
  EXPECT_GT(written, 400u);
  EXPECT_LT(written, 2000u);
  EXPECT_GE(store.tileCount(), written * 9 / 10) << "nearly every tile written holds part of the rut";
}

TEST(BeyondWindow, TeleportsAndNonFiniteStampsAreNotStored) {
  SnowWindow window(kSmall);
  PrintTileStore store;
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  std::vector<Stamp> stamps{capsule({100.f, 100.f}, {5000.f, 9000.f}, 0.1f, kCover, 0.1f),
                            capsule({nan, 100.f}, {100.f, 100.f}, 0.1f, kCover, 0.1f),
                            capsule({inf, 0.f}, {inf, 0.f}, 0.1f, kCover, 0.1f),
                            capsule({3e9f, 0.f}, {3e9f, 0.f}, 0.1f, kCover, 0.1f)};
  EXPECT_EQ(stampBeyondWindow(window, stamps, store, 0), 0u);
  EXPECT_EQ(store.tileCount(), 0u);
}

}  // namespace
}  // namespace wg::snow
