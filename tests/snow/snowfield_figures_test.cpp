// The snowfield's movers as articulated figures (snowfield_figures.hpp): a walker's
// planted foot stands in the print its footfall pressed, the swinging foot travels from
// one print to the next of the same side, and the vehicle's wheels run in its ruts.
#include "host/snowfield/snowfield_figures.hpp"

#include <gtest/gtest.h>

namespace wg::snow {
namespace {

// A gentle slope, so the heights are checked too.
FigureGround slope() { return {[](float x, float z) { return 0.1f * x + 0.05f * z; }, 0.04f}; }

Walker walker() {
  Walker w;
  w.path = ScriptedPath({{-2.f, 1.f}, {6.f, 4.f}}, 1.3f);
  return w;
}

TEST(SnowfieldFigures, PlantedFeetStandInTheirPrints) {
  Walker w = walker();
  FigureGround g = slope();
  for (int k = 0; k < 8; ++k) {
    auto [left, right] = walkerFeet(w, float(k) * w.stepLength + 1e-4f, g);
    glm::vec3 foot = k % 2 == 0 ? left : right;  // even footfalls are left feet
    glm::vec2 print = footfall(w, k);
    EXPECT_NEAR(foot.x, print.x, 1e-3f) << k;
    EXPECT_NEAR(foot.z, print.y, 1e-3f) << k;
    EXPECT_NEAR(foot.y, g.height(print.x, print.y) + g.floor, 1e-3f) << k;
  }
}

TEST(SnowfieldFigures, SwingingFootGoesFromPrintToPrintAndLifts) {
  Walker w = walker();
  FigureGround g = slope();
  const int k = 3;  // right foot planted; the left swings from print 2 to print 4
  auto at = [&](float u) { return walkerFeet(w, (float(k) + u) * w.stepLength, g).first; };
  glm::vec2 from = footfall(w, k - 1), to = footfall(w, k + 1);
  EXPECT_NEAR(glm::distance(glm::vec2(at(0.f).x, at(0.f).z), from), 0.f, 1e-3f);
  EXPECT_NEAR(glm::distance(glm::vec2(at(0.999f).x, at(0.999f).z), to), 0.f, 2e-2f);
  glm::vec3 mid = at(0.5f);
  glm::vec2 between = 0.5f * (from + to);
  EXPECT_GT(mid.y, g.height(between.x, between.y) + g.floor + 0.1f) << "the foot clears the snow mid-swing";
}

TEST(SnowfieldFigures, WheelsRunInTheRuts) {
  Vehicle v;
  v.path = ScriptedPath({{-10.f, 2.f}, {10.f, 2.f}}, 3.f);
  std::map<std::string, glm::mat4> models;
  poseVehicle(v, "car", 7.f, slope(), models);
  ASSERT_EQ(vehicleParts("car", v).size(), 5u);
  for (int i = 0; i < 4; ++i) {
    glm::vec3 centre(models.at("carWheel" + std::to_string(i))[3]);
    // The path runs along +x at z = 2: the ruts lie half the track either side of it.
    EXPECT_NEAR(std::abs(centre.z - 2.f), 0.5f * v.track, 1e-4f) << i;
    EXPECT_NEAR(centre.y - 0.35f, slope().height(centre.x, centre.z) + slope().floor, 1e-4f) << "resting in the rut";
  }
}

}  // namespace
}  // namespace wg::snow
