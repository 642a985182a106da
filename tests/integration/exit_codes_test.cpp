// Exit 3 is for weathergen's own bugs only: mistakes on the command line or in the
// machine's setup are usage errors (exit 2) that name the fix.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "process_support.hpp"

namespace {

namespace fs = std::filesystem;
using wg::testing::runCommand;
using wg::testing::shellQuote;
using wg::testing::TempDir;

wg::testing::CommandResult render(const std::string& args) {
  return runCommand(wg::testing::kVulkanChildEnvironment + shellQuote(WG_CLI_PATH) + " render --scene rocks --size 16x16 -q " + args);
}

TEST(ExitCodes, FramesNamingAFileIsAUsageErrorBeforeRendering) {
  TempDir dir("wg-exit-codes");
  wg::testing::writeFile(dir.path() / "afile", "x");
  auto r = render("--timeline " + shellQuote(std::string(WG_SOURCE_DIR) + "/timelines/seasons.json") + " --frames " +
                  shellQuote((dir.path() / "afile").string()) + " -o " + shellQuote((dir.path() / "x.png").string()));
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("--frames"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir.path() / "x.png"));
}

TEST(ExitCodes, AnUnknownDeviceIsAUsageErrorNamingTheDevicesThere) {
  TempDir dir("wg-exit-codes");
  auto r = render("--device no-such-gpu -o " + shellQuote((dir.path() / "x.png").string()));
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("no-such-gpu"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("--device"), std::string::npos) << r.output;
}

}  // namespace
