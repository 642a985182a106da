#include "tests/snow/snow_gpu_support.hpp"

#include <memory>
#include <string>

namespace wg::snow::testing {

vk::Context* snowContext() {
  static std::unique_ptr<vk::Context> ctx = [] {
    std::string error;
    return vk::Context::create({"cpu", true}, error);
  }();
  return ctx.get();
}

void ValidatedGpuTest::SetUp() {
  if (!snowContext()) GTEST_SKIP() << "no Vulkan device";
  snowContext()->clearValidationMessages();
}

void ValidatedGpuTest::TearDown() {
  if (!snowContext()) return;
  for (const auto& m : snowContext()->validationMessages()) ADD_FAILURE() << "Vulkan validation: " << m;
}

}  // namespace wg::snow::testing
