// Large frames degrade instead of failing: the lit frame's targets are sized against the
// device's limits before anything is allocated (host/frame_target_plan.hpp).
#include "host/frame_target_plan.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace wg {
namespace {

constexpr std::uint64_t kGiB = 1ull << 30;

// lavapipe's: 16384 on a side, 2 GiB an allocation and a 2 GiB heap.
FrameLimits lavapipeLike() { return {16384, 2 * kGiB, 2 * kGiB, 8}; }

TEST(FrameTargetPlan, FramesThatFitKeepTheirSamples) {
  const FrameTargetPlan plan = planFrameTargets(1920, 1080, 4, lavapipeLike());
  EXPECT_EQ(plan.samples, 4u);
  EXPECT_EQ(plan.note, "");
}

TEST(FrameTargetPlan, ADeviceWithFewerSamplesIsNotANote) {
  FrameLimits limits = lavapipeLike();
  limits.samples = 1;
  const FrameTargetPlan plan = planFrameTargets(960, 540, 4, limits);
  EXPECT_EQ(plan.samples, 1u);
  EXPECT_EQ(plan.note, "");
}

// Lit frames are RGBA16F: 5793x5793 at 4 samples needs 2.1 GiB of targets (over the
// 2 GiB heap), at 2 samples 1.4 GiB; 8192x8192 needs 2.75 GiB even at 2 samples.
TEST(FrameTargetPlan, LargeFramesFallBackToFewerSamples) {
  const FrameTargetPlan at5793 = planFrameTargets(5793, 5793, 4, lavapipeLike());
  EXPECT_EQ(at5793.samples, 2u);
  EXPECT_NE(at5793.note.find("rendering with 2 samples"), std::string::npos) << at5793.note;
  const FrameTargetPlan at8192 = planFrameTargets(8192, 8192, 4, lavapipeLike());
  EXPECT_EQ(at8192.samples, 1u);
  EXPECT_NE(at8192.note.find("8192x8192 at 4 MSAA samples"), std::string::npos) << at8192.note;
}

// 8192x8192 at 4 samples is one 2 GiB image, at 2 samples 1 GiB.
TEST(FrameTargetPlan, AMultisampledImageOverTheAllocationLimitFallsBack) {
  FrameLimits limits = lavapipeLike();
  limits.largestAllocation = kGiB;
  limits.budget = 100 * kGiB;
  EXPECT_EQ(planFrameTargets(8192, 8192, 4, limits).samples, 2u);
}

TEST(FrameTargetPlan, AFrameOverTheBudgetFallsBackToo) {
  FrameLimits limits = lavapipeLike();
  limits.largestAllocation = 4 * kGiB;
  limits.budget = 3 * kGiB / 2;  // 4096x4096 takes 1.8 GiB at 8 samples, 1.1 GiB at 4
  EXPECT_EQ(planFrameTargets(4096, 4096, 8, limits).samples, 4u);
}

TEST(FrameTargetPlan, AFrameThatFitsAtNoSampleCountNamesTheLargestThatDoes) {
  FrameLimits limits = lavapipeLike();
  limits.largestAllocation = 256ull << 20;  // 16 M pixels of RGBA32F at one sample
  const FrameTargetPlan plan = planFrameTargets(8192, 4096, 4, limits);
  EXPECT_EQ(plan.samples, 0u);
  EXPECT_NE(plan.note.find("8192x4096"), std::string::npos) << plan.note;
  EXPECT_NE(plan.note.find("the largest of this shape that fits is 5792x2896"), std::string::npos) << plan.note;
}

TEST(FrameTargetPlan, ASideOverTheDeviceLimitIsRefused) {
  FrameLimits limits = lavapipeLike();
  limits.largestSide = 4096;
  const FrameTargetPlan plan = planFrameTargets(8192, 100, 1, limits);
  EXPECT_EQ(plan.samples, 0u);
  EXPECT_NE(plan.note.find("4096x50"), std::string::npos) << plan.note;
}

// What still runs out of memory after planning is a resource limit too, which render
// reports with exit 1, not an internal error.
TEST(VulkanCheck, OutOfMemoryIsItsOwnError) {
  EXPECT_THROW(vk::check(VK_ERROR_OUT_OF_DEVICE_MEMORY, "vkAllocateMemory"), vk::OutOfMemory);
  EXPECT_THROW(vk::check(VK_ERROR_OUT_OF_HOST_MEMORY, "vkAllocateMemory"), vk::OutOfMemory);
  try {
    vk::check(VK_ERROR_DEVICE_LOST, "vkQueueSubmit");
    FAIL() << "no exception";
  } catch (const vk::OutOfMemory&) {
    FAIL() << "a lost device is not a memory limit";
  } catch (const std::runtime_error&) {
  }
  EXPECT_NO_THROW(vk::check(VK_SUCCESS, "vkCreateImage"));
}

}  // namespace
}  // namespace wg
