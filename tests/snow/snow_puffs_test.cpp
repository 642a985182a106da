// Snow puffs: the GPU particle step, and soft fading against the scene's
// depth (seed 3.3.2), on lavapipe with validation on.
#include "host/snowfield/snow_puffs.hpp"

#include <gtest/gtest.h>

#include "tests/snow/snow_gpu_support.hpp"

namespace wg::snow {
namespace {

using testing::snowContext;
using SnowPuffTest = testing::ValidatedGpuTest;

TEST_F(SnowPuffTest, PuffsRiseFallDriftAndDie) {
  PuffSettings settings;
  settings.capacity = 256;
  SnowPuffs puffs(*snowContext(), settings);
  glm::vec3 foot(2.f, 0.3f, -1.f);
  puffs.emit(std::span(&foot, 1));
  EXPECT_EQ(puffs.live(), std::size_t(settings.particlesPerFootfall));
  const double step = 1.0 / 30.0;
  for (int i = 0; i < 3; ++i) puffs.simulate(step, glm::vec2(0.f));
  glm::vec3 centre(0.f);
  float highest = foot.y;
  for (const Particle& p : puffs.particles())
    if (p.velocityLife.w > 0.f) {
      EXPECT_NEAR(p.positionAge.w, 3 * step, 1e-4);
      centre += glm::vec3(p.positionAge) / float(settings.particlesPerFootfall);
      highest = std::max(highest, p.positionAge.y);
    }
  EXPECT_GT(centre.y, foot.y) << "the cloud is kicked up";
  EXPECT_GT(highest, foot.y + 0.05f);
  EXPECT_NEAR(centre.x, foot.x, 0.15f);
  // A wind along +x carries the cloud downwind.
  for (int i = 0; i < 6; ++i) puffs.simulate(step, glm::vec2(4.f, 0.f));
  glm::vec3 later(0.f);
  for (const Particle& p : puffs.particles())
    if (p.velocityLife.w > 0.f) later += glm::vec3(p.positionAge) / float(puffs.live());
  EXPECT_GT(later.x, centre.x + 0.1f);
  // Nothing outlives its lifetime (at most 1.3 x the setting).
  for (int i = 0; i < 60; ++i) puffs.simulate(step, glm::vec2(0.f));
  EXPECT_EQ(puffs.live(), 0u);
}

}  // namespace
}  // namespace wg::snow
