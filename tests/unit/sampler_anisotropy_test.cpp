// Which devices filter textures anisotropically: GPUs up to 16x, CPU devices never
// (lavapipe's anisotropic path takes minutes for grazing views).
#include "vulkan/sampler_anisotropy.hpp"

#include <gtest/gtest.h>

namespace wg::vk {
namespace {

TEST(SamplerAnisotropy, CpuDevicesSampleTrilinearOnly) {
  EXPECT_EQ(samplerAnisotropyFor(VK_PHYSICAL_DEVICE_TYPE_CPU, true, 16.f), 1.f);
  EXPECT_EQ(samplerAnisotropyFor(VK_PHYSICAL_DEVICE_TYPE_CPU, true, 4.f), 1.f);
}

TEST(SamplerAnisotropy, GpusFilterUpToSixteenTimes) {
  for (VkPhysicalDeviceType gpu : {VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU, VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU,
                                   VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU}) {
    EXPECT_EQ(samplerAnisotropyFor(gpu, true, 16.f), 16.f);
    EXPECT_EQ(samplerAnisotropyFor(gpu, true, 64.f), 16.f);  // never past 16x
    EXPECT_EQ(samplerAnisotropyFor(gpu, true, 8.f), 8.f);    // nor past the device's limit
  }
}

TEST(SamplerAnisotropy, OffWithoutTheFeature) {
  EXPECT_EQ(samplerAnisotropyFor(VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU, false, 16.f), 1.f);
}

}  // namespace
}  // namespace wg::vk
