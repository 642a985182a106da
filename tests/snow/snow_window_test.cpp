// The sliding window's addressing: world <-> texel, toroidal storage, tile-aligned
// recentring targets.
#include "snow/snow_window.hpp"

#include <gtest/gtest.h>

#include <set>

namespace wg::snow {
namespace {

TEST(SnowWindow, DefaultIsThe41MetreMapOfTheShippedTechnique) {
  SnowWindow w;
  EXPECT_EQ(w.resolution(), 1024);
  EXPECT_FLOAT_EQ(w.texelSize(), 0.04f);
  EXPECT_NEAR(w.extent(), 40.96f, 1e-3f);
}

TEST(SnowWindow, WorldToTexelFloorsNegativeCoordinates) {
  SnowWindow w;
  EXPECT_EQ(w.texelAt({0.01f, 0.05f}), glm::ivec2(0, 1));
  EXPECT_EQ(w.texelAt({-0.01f, -0.05f}), glm::ivec2(-1, -2));
  EXPECT_NEAR(w.texelCentre({-1, 2}).x, -0.02f, 1e-6f);
  EXPECT_NEAR(w.texelCentre({-1, 2}).y, 0.10f, 1e-6f);
}

TEST(SnowWindow, StorageIsToroidalAndCoversEverySlotOnce) {
  SnowWindow w({64, 0.04f, 16});
  w.setOrigin({-80, 48});
  std::set<std::size_t> slots;
  for (int z = 0; z < 64; ++z)
    for (int x = 0; x < 64; ++x) slots.insert(w.storageIndex(w.origin() + glm::ivec2(x, z)));
  EXPECT_EQ(slots.size(), 64u * 64u);
  // A texel and the one a window-width away share a slot: recentring reuses it.
  EXPECT_EQ(w.storageIndex({-5, 7}), w.storageIndex({-5 + 64, 7 - 64}));
}

TEST(SnowWindow, OriginKeepsTheCameraInTheCentralTile) {
  SnowWindow w({128, 0.04f, 16});
  for (glm::vec2 camera : {glm::vec2(0.f), glm::vec2(-3.3f, 7.9f), glm::vec2(100.f, -250.f)}) {
    glm::ivec2 origin = w.originFor(camera);
    EXPECT_EQ(origin.x % 16, 0);
    EXPECT_EQ(origin.y % 16, 0);
    glm::ivec2 rel = w.texelAt(camera) - origin;
    EXPECT_GE(rel.x, 64);
    EXPECT_LT(rel.x, 64 + 16);
    EXPECT_GE(rel.y, 64);
    EXPECT_LT(rel.y, 64 + 16);
  }
}

TEST(SnowWindow, RejectsResolutionsThatAreNotAnEvenNumberOfTiles) {
  EXPECT_THROW(SnowWindow({100, 0.04f, 32}), std::invalid_argument);
  EXPECT_THROW(SnowWindow({96, 0.04f, 32}), std::invalid_argument);
  EXPECT_THROW(SnowWindow({128, 0.f, 32}), std::invalid_argument);
  EXPECT_THROW(SnowWindow({1024, 0.04f, 512}), std::invalid_argument);
}

}  // namespace
}  // namespace wg::snow
