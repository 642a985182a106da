// Refill is spread over frames: each call refills at most refillTilesPerFrame tiles, only
// tiles that hold prints, and every tile catches up exactly on what it is owed, in the
// window or after a trip through the print store.
#include "snow/refill_schedule.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "snow/deformation_map.hpp"
#include "snow/deformation_texel.hpp"

namespace wg::snow {
namespace {

const WindowSettings kSmall{128, 0.04f, 16};  // 8 x 8 tiles of 0.64 m, 4 refilled per call
constexpr double kOneCentimetre = 0.01;

// Small discs 0.1 m deep, one in the middle of each of `count` tiles along a row and up.
std::vector<glm::vec2> printTiles(DeformationMap& map, int count) {
  std::vector<glm::vec2> centres;
  float tile = kSmall.texelSize * float(kSmall.tileTexels);
  for (int i = 0; i < count; ++i)
    centres.push_back(glm::vec2(-2.56f) + (glm::vec2(i % 8, i / 8) + 0.5f) * tile);
  std::vector<Stamp> stamps;
  for (glm::vec2 c : centres) stamps.push_back(capsule(c, c, 0.1f, SnowCover{0.3f}, 0.1f));
  map.apply(stamps);
  return centres;
}

int changedTiles(const std::vector<glm::vec2>& centres, const std::vector<float>& before, DeformationMap& map) {
  int changed = 0;
  for (std::size_t i = 0; i < centres.size(); ++i) changed += map.depthAt(centres[i]) != before[i];
  return changed;
}

TEST(RefillSchedule, EachCallRefillsAtMostTheBudgetAndAllCatchUpExactly) {
  DeformationMap map(kSmall);
  auto centres = printTiles(map, 40);
  std::vector<float> before;
  for (glm::vec2 c : centres) before.push_back(map.depthAt(c));
  map.refill(kOneCentimetre, 1.0);
  EXPECT_EQ(changedTiles(centres, before, map), int(kSmall.refillTilesPerFrame));
  const int frames = (40 + int(kSmall.refillTilesPerFrame) - 1) / int(kSmall.refillTilesPerFrame);
  for (int frame = 1; frame < frames; ++frame) {
    map.refill(0.0, 1.0 / 60.0);
    EXPECT_EQ(changedTiles(centres, before, map), std::min(40, (frame + 1) * int(kSmall.refillTilesPerFrame)));
  }
  EXPECT_EQ(changedTiles(centres, before, map), 40);
  for (std::size_t i = 0; i < centres.size(); ++i)
    EXPECT_NEAR(map.depthAt(centres[i]), before[i] - 0.01f, 1.5f * kDepthQuantum) << i;
}

TEST(RefillSchedule, OnlyTilesWithPrintsAreVisitedUntilTheyAreFull) {
  SnowWindow window(kSmall);
  RefillSchedule schedule(window);
  EXPECT_TRUE(schedule.due(window, 100, 64).empty()) << "untouched snow owes nothing";
  Stamp s = capsule({0.3f, 0.3f}, {0.3f, 0.3f}, 0.05f, SnowCover{0.3f}, 0.002f);  // 2 mm: 20 quanta
  schedule.stamped(window, std::span(&s, 1), 100);
  EXPECT_EQ(schedule.printedTiles(), 1u);
  EXPECT_TRUE(schedule.due(window, 100, 64).empty()) << "nothing owed yet";
  auto due = schedule.due(window, 112, 64);
  ASSERT_EQ(due.size(), 1u);
  EXPECT_EQ(due[0].tile, glm::ivec2(0, 0));
  EXPECT_EQ(due[0].quanta, 12u);
  due = schedule.due(window, 130, 64);
  ASSERT_EQ(due.size(), 1u);
  EXPECT_EQ(due[0].quanta, 18u);
  EXPECT_EQ(schedule.printedTiles(), 0u) << "12 + 18 quanta filled a 20-quanta print";
  EXPECT_TRUE(schedule.due(window, 1000, 64).empty());
}

TEST(RefillSchedule, ATileThatLeavesBeforeItsTurnCatchesUpWhenItReturns) {
  DeformationMap map(kSmall);
  auto centres = printTiles(map, 40);
  map.refill(kOneCentimetre, 1.0);  // 4 of 40 tiles refilled, 36 still owe 1 cm
  map.follow({60.f, 0.f});          // all leave
  map.refill(kOneCentimetre, 1.0);  // and 1 cm more while away
  map.follow({0.f, 0.f});
  for (int frame = 0; frame < 10; ++frame) map.refill(0.0, 1.0 / 60.0);
  for (std::size_t i = 0; i < centres.size(); ++i)
    EXPECT_NEAR(map.depthAt(centres[i]), 0.08f, 1.5f * kDepthQuantum) << i;
}

}  // namespace
}  // namespace wg::snow
