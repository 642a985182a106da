// vk::Handle destroys each object exactly once, with its parent, in the order owners
// expect; checked with a stand-in destroy function, so no device is needed.
#include "vulkan/vulkan_handle.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <utility>
#include <vector>

namespace wg::vk {
namespace {

struct Destroyed {
  VkDevice device;
  VkSampler sampler;
};
std::vector<Destroyed> destroyed;

void destroySampler(VkDevice device, VkSampler sampler, const VkAllocationCallbacks* allocator) {
  EXPECT_EQ(allocator, nullptr);
  destroyed.push_back({device, sampler});
}

std::vector<VkInstance> destroyedInstances;
void destroyInstance(VkInstance instance, const VkAllocationCallbacks*) { destroyedInstances.push_back(instance); }

using Sampler = Handle<VkSampler, destroySampler>;
using Instance = Handle<VkInstance, destroyInstance, NoParent>;

// Distinct non-null handles without a device.
template <typename T>
T fake(std::uintptr_t n) {
  return reinterpret_cast<T>(n);
}

class VulkanHandle : public ::testing::Test {
 protected:
  void SetUp() override {
    destroyed.clear();
    destroyedInstances.clear();
  }
};

TEST_F(VulkanHandle, DestroysOnceWithItsDevice) {
  { Sampler s(fake<VkDevice>(1), fake<VkSampler>(2)); }
  ASSERT_EQ(destroyed.size(), 1u);
  EXPECT_EQ(destroyed[0].device, fake<VkDevice>(1));
  EXPECT_EQ(destroyed[0].sampler, fake<VkSampler>(2));
}

TEST_F(VulkanHandle, EmptyHandlesDestroyNothing) {
  { Sampler s; EXPECT_FALSE(s); }
  { Sampler s(fake<VkDevice>(1), VK_NULL_HANDLE); }
  EXPECT_TRUE(destroyed.empty());
}

TEST_F(VulkanHandle, MoveTransfersOwnership) {
  {
    Sampler a(fake<VkDevice>(1), fake<VkSampler>(2));
    Sampler b(std::move(a));
    EXPECT_FALSE(a);
    EXPECT_EQ(b.get(), fake<VkSampler>(2));
    EXPECT_TRUE(destroyed.empty());
  }
  ASSERT_EQ(destroyed.size(), 1u);
  EXPECT_EQ(destroyed[0].sampler, fake<VkSampler>(2));
}

TEST_F(VulkanHandle, MoveAssignmentDestroysTheOldObjectFirst) {
  Sampler a(fake<VkDevice>(1), fake<VkSampler>(2));
  Sampler b(fake<VkDevice>(3), fake<VkSampler>(4));
  a = std::move(b);
  ASSERT_EQ(destroyed.size(), 1u);
  EXPECT_EQ(destroyed[0].device, fake<VkDevice>(1));
  EXPECT_EQ(destroyed[0].sampler, fake<VkSampler>(2));
  a.reset();
  ASSERT_EQ(destroyed.size(), 2u);
  EXPECT_EQ(destroyed[1].device, fake<VkDevice>(3));  // the parent moved with it
  EXPECT_EQ(destroyed[1].sampler, fake<VkSampler>(4));
  a.reset();
  EXPECT_EQ(destroyed.size(), 2u);
}

TEST_F(VulkanHandle, MembersGoInReverseDeclarationOrder) {
  struct Owner {
    Sampler first{fake<VkDevice>(1), fake<VkSampler>(10)};
    Sampler second{fake<VkDevice>(1), fake<VkSampler>(20)};
  };
  { Owner owner; }
  ASSERT_EQ(destroyed.size(), 2u);
  EXPECT_EQ(destroyed[0].sampler, fake<VkSampler>(20));
  EXPECT_EQ(destroyed[1].sampler, fake<VkSampler>(10));
}

TEST_F(VulkanHandle, ObjectsWithoutAParentDestroyThemselves) {
  { Instance i(fake<VkInstance>(7)); }
  ASSERT_EQ(destroyedInstances.size(), 1u);
  EXPECT_EQ(destroyedInstances[0], fake<VkInstance>(7));
  static_assert(sizeof(Instance) == sizeof(VkInstance), "no room spent on a missing parent");
}

}  // namespace
}  // namespace wg::vk
