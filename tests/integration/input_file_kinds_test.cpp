// Every input is read only when it is a regular file of bounded size: a FIFO would
// block forever and /dev/zero never ends. Each command says so, promptly, with exit 1
// (or 2 for the timeline, a command-line input) and no signal.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <string>

#include "process_support.hpp"

namespace {

namespace fs = std::filesystem;
using wg::testing::runCommand;
using wg::testing::shellQuote;
using wg::testing::TempDir;

// `timeout` turns a hang into exit 124, which the expectations below reject.
wg::testing::CommandResult run(const std::string& args) {
  return runCommand("timeout 20 " + shellQuote(WG_CLI_PATH) + " " + args);
}

TEST(InputFileKinds, FifosAndDevicesAreRefusedNotRead) {
  TempDir dir("wg-input-kinds");
  fs::path fifo = dir.path() / "fifo.json";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::string out = shellQuote((dir.path() / "out").string());
  for (const std::string& input : {fifo.string(), std::string("/dev/zero")}) {
    SCOPED_TRACE(input);
    for (const std::string& command : {"compile " + shellQuote(input) + " -o " + out, "eval " + shellQuote(input),
                                       "import " + shellQuote(input) + " -o " + out}) {
      auto r = run(command);
      EXPECT_EQ(r.exitCode, 1) << command << "\n" << r.output;
      EXPECT_NE(r.output.find("not a regular file"), std::string::npos) << r.output;
    }
    auto r = run("render --scene valley --size 16x16 -q --timeline " + shellQuote(input) + " -o " +
                 shellQuote((dir.path() / "x.png").string()));
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("not a regular file"), std::string::npos) << r.output;
  }
  EXPECT_FALSE(fs::exists(dir.path() / "out"));
}

}  // namespace
