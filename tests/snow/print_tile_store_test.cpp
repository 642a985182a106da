// The print store's budget: past it, the tiles stored longest ago go first, and the
// store never holds more than its budget.
#include "snow/print_tile_store.hpp"

#include <gtest/gtest.h>

#include "snow/deformation_map.hpp"

namespace wg::snow {
namespace {

StoredTile tileOf(std::size_t texels, std::uint64_t refill) {
  std::vector<std::uint32_t> dense(32 * 32, 0u);
  for (std::size_t i = 0; i < texels; ++i) dense[i * 3] = 0x00100000u + std::uint32_t(i);
  return packTile(dense, refill);
}

TEST(PrintTileStore, TheBudgetEvictsTheOldestTilesFirst) {
  PrintTileStore probe;
  probe.put({0, 0}, tileOf(100, 0));
  const std::size_t oneTile = probe.memoryBytes();
  PrintTileStore store(5 * oneTile);
  for (int i = 0; i < 5; ++i) store.put({i, 0}, tileOf(100, std::uint64_t(i)));
  EXPECT_EQ(store.tileCount(), 5u);
  EXPECT_EQ(store.tilesDropped(), 0u);
  store.put({2, 0}, tileOf(100, 7));  // rewritten: now the newest
  store.put({9, 9}, tileOf(100, 8));  // over budget: the oldest, (0, 0), goes
  EXPECT_FALSE(store.holds({0, 0}));
  EXPECT_TRUE(store.holds({1, 0}));
  store.put({8, 8}, tileOf(100, 9));  // then (1, 0); (2, 0) was refreshed and stays
  EXPECT_FALSE(store.holds({1, 0}));
  EXPECT_TRUE(store.holds({2, 0}));
  EXPECT_EQ(store.tilesDropped(), 2u);
  EXPECT_LE(store.memoryBytes(), store.budgetBytes());
  std::vector<glm::ivec2> order;
  store.forEachOldestFirst([&](glm::ivec2 tile, const StoredTile&) { order.push_back(tile); });
  EXPECT_EQ(order, (std::vector<glm::ivec2>{{3, 0}, {4, 0}, {2, 0}, {9, 9}, {8, 8}}));
}

TEST(PrintTileStore, AWalkAwayStaysWithinTheBudget) {
  WindowSettings settings{128, 0.04f, 16};
  settings.printStoreBudget = 16 * 1024;
  DeformationMap map(settings);
  for (float x = 0.f; x < 200.f; x += 0.5f) {
    Stamp s = capsule({x, 0.f}, {x + 0.5f, 0.f}, 0.15f, SnowCover{0.2f}, 0.1f);
    map.follow({x, 0.f});
    map.apply(std::span(&s, 1));
    ASSERT_LE(map.store().memoryBytes(), settings.printStoreBudget);
  }
  EXPECT_GT(map.store().tilesDropped(), 0u);
  // The newest prints, just behind the window, are kept; the first ones are gone.
  glm::ivec2 behind(map.window().origin().x / int(settings.tileTexels) - 1, 0);  // the rut's row of tiles
  EXPECT_TRUE(map.store().holds(behind));
  map.follow({0.f, 0.f});
  EXPECT_EQ(map.depthAt({1.f, 0.f}), 0.f);
}

TEST(PrintTileStore, TakingATileGivesItsMemoryBack) {
  PrintTileStore store;
  store.put({3, 4}, tileOf(50, 2));
  EXPECT_GT(store.memoryBytes(), 50u * 6u);
  auto tile = store.take({3, 4});
  ASSERT_TRUE(tile);
  EXPECT_EQ(tile->heights.size(), 50u);
  EXPECT_EQ(tile->refillAtEviction, 2u);
  EXPECT_EQ(store.memoryBytes(), 0u);
  store.put({1, 1}, StoredTile{});  // empty: not kept
  EXPECT_EQ(store.tileCount(), 0u);
}

}  // namespace
}  // namespace wg::snow
