// What a SceneRenderer does before its first render (the sky-exposure map) is
// validation-clean too: render() clears the messages it starts with, so a test that
// only looks after rendering would not see them.
#include <gtest/gtest.h>

#include "render_support.hpp"

namespace wg::testing {
namespace {

TEST(SceneRendererSetup, TheSkyExposureMapIsValidationClean) {
  if (!renderContext()) GTEST_SKIP() << "no Vulkan driver (install mesa-vulkan-drivers)";
  renderContext()->clearValidationMessages();
  {
    SceneRenderer renderer(*renderContext(), *scene::makeScene("valley"), std::string(WG_SOURCE_DIR) + "/graphs");
    EXPECT_GT(renderer.exposureHeights().size(), 0u);
  }
  expectNoValidationMessages();
}

}  // namespace
}  // namespace wg::testing
