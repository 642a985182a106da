// On lavapipe with validation: prints made outside the GPU map's window go to its print
// store and come back into the buffers, texel for texel as the CPU model has them, when
// the window reaches them.
#include <gtest/gtest.h>

#include "snow/deformation_map.hpp"
#include "snow/gpu_deformation_map.hpp"
#include "snow/snow_interactors.hpp"
#include "tests/snow/snow_gpu_support.hpp"

namespace wg::snow {
namespace {

using GpuBeyondWindow = testing::ValidatedGpuTest;

TEST_F(GpuBeyondWindow, PrintsMadeFarAwayAppearWhenTheWindowArrives) {
  const WindowSettings small{128, 0.04f, 16};
  const glm::vec2 far{-45.f, 30.f};
  GpuDeformationMap gpu(*testing::snowContext(), small);
  DeformationMap cpu(small);
  Vehicle v;
  v.path = ScriptedPath({far, far + glm::vec2(1.2f, 0.6f)}, 3.f);
  for (double t = 0.0; t < 1.0; t += 0.1) {
    std::vector<Stamp> stamps;
    vehicleStamps(v, t - 0.1, t, SnowCover{0.12f}, stamps);
    gpu.apply(stamps);
    cpu.apply(stamps);
  }
  EXPECT_GT(gpu.store().tileCount(), 0u);
  glm::vec2 middle = v.path.pointAt(0.5f * v.path.length());
  gpu.follow(middle);
  cpu.follow(middle);
  EXPECT_EQ(gpu.store().tileCount(), 0u);
  glm::vec2 heading = v.path.headingAt(0.5f), left(-heading.y, heading.x);
  EXPECT_GT(gpu.depthAt(v.path.pointAt(0.5f) + left * (0.5f * v.track)), 0.05f);
  auto heights = gpu.texels().heights;
  EXPECT_TRUE(std::equal(heights.begin(), heights.end(), cpu.texels().heights.begin()));
}

}  // namespace
}  // namespace wg::snow
