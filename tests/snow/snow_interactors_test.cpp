// Movers stamp only when they move: a parked vehicle or a walker standing still adds
// nothing, however many frames pass, and a creeping vehicle still leaves an unbroken rut.
#include "snow/snow_interactors.hpp"

#include <gtest/gtest.h>

#include "snow/deformation_map.hpp"

namespace wg::snow {
namespace {

const SnowCover kCover{0.12f};
constexpr double kFrame = 1.0 / 60.0;

std::size_t vehicleStampsOver(const Vehicle& v, double from, int frames) {
  std::vector<Stamp> stamps;
  for (int f = 0; f < frames; ++f) vehicleStamps(v, from + (f - 1) * kFrame, from + f * kFrame, kCover, stamps);
  return stamps.size();
}

TEST(SnowInteractors, AParkedVehicleAddsNoStamps) {
  Vehicle parked;
  parked.path = ScriptedPath({{1.f, 2.f}}, 0.f);
  std::vector<Stamp> first;
  vehicleStamps(parked, -kFrame, 0.0, kCover, first);
  EXPECT_EQ(first.size(), 2u) << "the wheels press in once, where the vehicle stands";
  EXPECT_EQ(vehicleStampsOver(parked, kFrame, 600), 0u);
}

TEST(SnowInteractors, AVehicleAtTheEndOfItsPathStopsStamping) {
  Vehicle v;
  v.path = ScriptedPath({{0.f, 0.f}, {3.f, 0.f}}, 6.f);  // there after half a second
  EXPECT_GT(vehicleStampsOver(v, 0.0, 40), 0u);
  EXPECT_EQ(vehicleStampsOver(v, 1.0, 600), 0u);
}

TEST(SnowInteractors, AWalkerStandingStillAddsNoStamps) {
  Walker w;
  w.path = ScriptedPath({{0.f, 0.f}, {1.f, 0.f}}, 1.f);
  std::vector<Stamp> stamps;
  for (int f = 0; f < 600; ++f) walkerStamps(w, 2.0 + (f - 1) * kFrame, 2.0 + f * kFrame, kCover, stamps);
  EXPECT_TRUE(stamps.empty());
}

TEST(SnowInteractors, ACreepingVehicleStampsEveryFewFramesWithoutGaps) {
  const WindowSettings small{128, 0.04f, 16};
  DeformationMap map(small);
  Vehicle v;
  v.path = ScriptedPath({{-1.f, 0.f}, {1.f, 0.f}}, 0.3f);  // 5 mm a frame, a quarter of rutStep
  std::size_t stamps = 0;
  for (int f = 0; f * kFrame < 7.0; ++f) {
    std::vector<Stamp> frame;
    vehicleStamps(v, (f - 1) * kFrame, f * kFrame, kCover, frame);
    stamps += frame.size();
    map.apply(frame);
  }
  EXPECT_LT(stamps, 2u * 7u * 60u / 3u) << "fewer than one rut pair every three frames";
  float depth = std::min(v.sink, deepestPrint(kCover));
  for (float x = -1.f; x <= 1.f; x += small.texelSize) EXPECT_NEAR(map.depthAt({x, 0.5f * v.track}), depth, 2e-3f) << x;
}

}  // namespace
}  // namespace wg::snow
