// The device the snow GPU tests run on (lavapipe, validation layers always on), and a
// fixture that fails a test on any validation message.
#pragma once
#include <gtest/gtest.h>

#include "vulkan/vulkan_context.hpp"

namespace wg::snow::testing {

vk::Context* snowContext();  // null (and a skip) only when no Vulkan driver exists

class ValidatedGpuTest : public ::testing::Test {
 protected:
  void SetUp() override;
  void TearDown() override;
};

}  // namespace wg::snow::testing
