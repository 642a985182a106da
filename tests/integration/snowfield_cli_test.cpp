// weathergen render --scene snowfield: the CLI animates the interactive
// snow with the validation layers on and writes a labelled contact sheet, a frame
// strip and the single frames.
#include <gtest/gtest.h>

#include "host/image/png_file.hpp"
#include "tests/integration/process_support.hpp"

namespace wg::testing {
namespace {

TEST(SnowfieldCli, WritesAContactSheetAStripAndTheFrames) {
  TempDir dir("snowfield-cli");
  std::string sheet = (dir.path() / "snowfield.png").string();
  CommandResult r = runCommand(kVulkanChildEnvironment + shellQuote(WG_CLI_PATH) +
                               " render --scene snowfield --size 96x54 --samples 1 --validation -q -o " +
                               shellQuote(sheet) + " --frames " + shellQuote((dir.path() / "frames").string()));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  std::string error;
  auto strip = image::readPng((dir.path() / "snowfield.strip.png").string(), error);
  ASSERT_TRUE(strip) << error;
  constexpr int kMoments = 5;  // forming, done, leaving, away, back
  EXPECT_GE(strip->width, kMoments * 96);
  EXPECT_EQ(strip->height, 54);
  EXPECT_TRUE(image::readPng(sheet, error)) << error;
  EXPECT_EQ(listFiles(dir.path() / "frames").size(), std::size_t(kMoments));
}

TEST(SnowfieldCli, RejectsATimeline) {
  CommandResult r = runCommand(shellQuote(WG_CLI_PATH) +
                               " render --scene snowfield --timeline timelines/seasons.json -o /dev/null");
  EXPECT_EQ(r.exitCode, 2) << r.output;
}

}  // namespace
}  // namespace wg::testing
