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

// The strip's name is taken by a directory: the contact sheet, already drawn, must not
// replace the old OUT.png on its own.
TEST(RenderOutputs, ATimelineThatCannotWriteItsStripLeavesTheContactSheetAsItWas) {
  TempDir dir("wg-render-outputs");
  writeFile(dir.path() / "t.json", kTwoStages);
  writeFile(dir.path() / "out.png", "old");
  fs::create_directory(dir.path() / "out.strip.png");
  CommandResult r = render("--scene rocks --timeline " + quoted(dir.path() / "t.json") + " --frames " +
                           quoted(dir.path() / "frames") + " -o " + quoted(dir.path() / "out.png"));
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("out.strip.png"), std::string::npos) << r.output;
  EXPECT_EQ(readFile(dir.path() / "out.png"), "old");
  EXPECT_FALSE(fs::exists(dir.path() / "frames")) << "a failed run leaves no folder it made";
  EXPECT_EQ(listFiles(dir.path()), (std::vector<std::string>{"out.png", "t.json"}));
  EXPECT_EQ(std::distance(fs::directory_iterator(dir.path()), fs::directory_iterator{}), 3) << "a staging folder was left";
}

// The second stage's picture name is taken: the first stage's picture is not written either.
TEST(RenderOutputs, AFramesPictureThatCannotBeWrittenLeavesNoOtherPicture) {
  TempDir dir("wg-render-outputs");
  writeFile(dir.path() / "t.json", kTwoStages);
  fs::create_directories(dir.path() / "frames" / "rocks-02-b.png");
  CommandResult r = render("--scene rocks --timeline " + quoted(dir.path() / "t.json") + " --frames " +
                           quoted(dir.path() / "frames") + " -o " + quoted(dir.path() / "out.png"));
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_EQ(std::distance(fs::directory_iterator(dir.path() / "frames"), fs::directory_iterator{}), 1)
      << "rocks-01-a.png was written";
  EXPECT_FALSE(fs::exists(dir.path() / "out.png"));
  EXPECT_FALSE(fs::exists(dir.path() / "out.strip.png"));
}

// A --frames folder the system will not create is the machine's setup, not a bug:
// exit 2 naming it, not exit 3 with an escaped exception.
TEST(RenderOutputs, AFramesFolderThatCannotBeCreatedIsAUsageError) {
  TempDir dir("wg-render-outputs");
  writeFile(dir.path() / "t.json", kTwoStages);
  CommandResult r = render("--scene rocks --timeline " + quoted(dir.path() / "t.json") +
                           " --frames /proc/self/no-such-folder -o " + quoted(dir.path() / "out.png"));
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("/proc/self/no-such-folder"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir.path() / "out.png"));
}

// A timeline's -o in a folder that does not exist fails as a single frame's does,
// and creates no folder.
TEST(RenderOutputs, ATimelineDoesNotCreateTheFolderOfItsOutput) {
  TempDir dir("wg-render-outputs");
  writeFile(dir.path() / "t.json", kTwoStages);
  CommandResult r = render("--scene rocks --timeline " + quoted(dir.path() / "t.json") + " -o " +
                           quoted(dir.path() / "missing" / "out.png"));
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_FALSE(fs::exists(dir.path() / "missing"));
}

// The stand is named after the graph file, and that name is in every --frames
// picture's name: an escape sequence, a newline or invalid UTF-8 in the graph's
// name must not reach a file name.
TEST(RenderOutputs, TheStandsFramesHaveFileSafeNamesWhateverTheGraphIsCalled) {
  TempDir dir("wg-render-outputs");
  writeFile(dir.path() / "t.json", kTwoStages);
  const fs::path graph = dir.path() / "\x1b[31m\xff\nrock.json";
  fs::copy_file(fs::path(WG_SOURCE_DIR) / "graphs" / "rock.json", graph);
  CommandResult r = render("--material " + quoted(graph) + " --timeline " + quoted(dir.path() / "t.json") +
                           " --frames " + quoted(dir.path() / "frames") + " -o " + quoted(dir.path() / "out.png"));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  for (const std::string& name : listFiles(dir.path() / "frames")) {
    SCOPED_TRACE(name);
    EXPECT_EQ(name.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-."),
              std::string::npos);
    EXPECT_EQ(name.rfind("stand-", 0), 0u);
  }
  EXPECT_EQ(listFiles(dir.path() / "frames").size(), 2u);
}

// --watch prints a line per render naming the output, on stdout, always.
TEST(RenderOutputs, WatchLinesQuoteTheOutputsName) {
  TempDir dir("wg-render-outputs");
  const fs::path out = dir.path() / "\x1b]0;title\x07out.png";
  CommandResult r = render("--material " + quoted(fs::path(WG_SOURCE_DIR) / "graphs" / "rock.json") +
                           " --watch --watch-renders 1 -o " + quoted(out));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("rendered"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find('\x1b'), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find('\x07'), std::string::npos) << r.output;
  EXPECT_TRUE(fs::exists(out));
}

// The snowfield writes its moments, its sheet and its strip together too, and names a
// file it cannot write without its control characters.
TEST(RenderOutputs, TheSnowfieldWritesNothingWhenOnePictureFailsAndQuotesItsName) {
  TempDir dir("wg-render-outputs");
  const fs::path out = dir.path() / "\x1b[31msnow.png";
  fs::create_directory(dir.path() / "\x1b[31msnow.strip.png");
  CommandResult r = render("--scene snowfield --frames " + quoted(dir.path() / "frames") + " -o " + quoted(out));
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("snow.strip.png"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find('\x1b'), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(out));
  EXPECT_FALSE(fs::exists(dir.path() / "frames"));
}

}  // namespace
}  // namespace wg::testing
