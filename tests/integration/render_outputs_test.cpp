// What render writes when its outputs are hostile: a FIFO or a device at an output's
// name, a directory where a picture goes, a --frames folder that cannot be made, names
// with control characters. A failed run leaves every output as it was; no user text
// reaches the terminal raw.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <iterator>
#include <string>

#include "process_support.hpp"

namespace wg::testing {
namespace {

namespace fs = std::filesystem;

// Two stages, "a" and "b": a contact sheet, a strip and two --frames pictures.
constexpr const char* kTwoStages = R"({"keyframes": [
  {"time": 0, "temperature": 5, "precipitation": 0, "label": "a"},
  {"time": 3600, "temperature": -5, "precipitation": 1, "label": "b"}
]})";

CommandResult render(const std::string& args) {
  return runCommand(kVulkanChildEnvironment + std::string("timeout 120 ") + shellQuote(WG_CLI_PATH) +
                    " render --size 16x16 --samples 1 -q " + args);
}

std::string quoted(const fs::path& path) { return shellQuote(path.string()); }

bool isFifo(const fs::path& path) {
  struct stat st {};
  return ::lstat(path.c_str(), &st) == 0 && S_ISFIFO(st.st_mode);
}

// Outputs are renamed into place, which would replace the FIFO (or, run as root,
// /dev/null) with a regular file. They are refused before anything is drawn, even
// through a link.
TEST(RenderOutputs, AFifoOrALinkToOneIsRefusedAsAnOutputNotReplaced) {
  TempDir dir("wg-render-outputs");
  const fs::path fifo = dir.path() / "fifo.png", link = dir.path() / "link.png";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  fs::create_symlink(fifo, link);
  for (const fs::path& out : {fifo, link}) {
    SCOPED_TRACE(out);
    CommandResult r = render("--scene rocks -o " + quoted(out));
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("a FIFO, not a regular file"), std::string::npos) << r.output;
  }
  CommandResult r = runCommand("timeout 60 " + shellQuote(WG_CLI_PATH) + " compile -q " +
                               quoted(fs::path(WG_SOURCE_DIR) / "graphs" / "rock.json") + " -o " +
                               quoted(dir.path() / "out") + " --depfile " + quoted(fifo));
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_TRUE(isFifo(fifo));
  EXPECT_TRUE(fs::is_symlink(link));
  EXPECT_FALSE(fs::exists(dir.path() / "out"));
}

}  // namespace
}  // namespace wg::testing
