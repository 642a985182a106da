// Batches: byte-identical output whatever -j is, depfiles for build systems, and no
// progress noise when stderr is not a terminal.
#include <gtest/gtest.h>

#include "process_support.hpp"

namespace wg {
namespace {

using testing::listFiles;
using testing::readFile;
using testing::runCommand;
using testing::shellQuote;
using testing::TempDir;
namespace fs = std::filesystem;

std::string allGraphs() {
  std::string list;
  for (const auto& g : testing::bundledGraphs()) list += " " + shellQuote(g.string());
  return list;
}

TEST(Batch, OutputIsByteIdenticalWhateverTheJobCount) {
  TempDir dir("jobs");
  for (const char* jobs : {"1", "2", "7"}) {
    auto r = runCommand(shellQuote(WG_CLI_PATH) + " compile" + allGraphs() + " -j" + jobs + " -o " +
                        shellQuote((dir.path() / jobs).string()));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(r.output, "") << "a batch on a pipe prints nothing";
  }
  auto reference = listFiles(dir.path() / "1");
  ASSERT_FALSE(reference.empty());
  for (const char* jobs : {"2", "7"}) {
    ASSERT_EQ(listFiles(dir.path() / jobs), reference);
    for (const auto& name : reference)
      EXPECT_TRUE(readFile(dir.path() / "1" / name) == readFile(dir.path() / jobs / name)) << name << " at -j" << jobs;
  }
}

TEST(Batch, DepfileListsEveryOutputAndInputEscaped) {
  TempDir dir("depfile");
  // A graph and an image file whose names need escaping.
  fs::create_directories(dir.path() / "my graphs");
  testing::writeFile(dir.path() / "my graphs" / "lit.json",
                     R"({"name": "lit", "nodes": [], "output": {"roughness": 0.4}})");
  fs::path depfile = dir.path() / "out.d";
  auto r = runCommand(shellQuote(WG_CLI_PATH) + " compile " + shellQuote((dir.path() / "my graphs" / "lit.json").string()) +
                      " " + shellQuote(std::string(WG_SOURCE_DIR) + "/graphs/rock.json") + " --depfile " +
                      shellQuote(depfile.string()) + " -o " + shellQuote((dir.path() / "out").string()));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  std::string d = readFile(depfile);
  EXPECT_NE(d.find("my\\ graphs/lit.json"), std::string::npos) << d;
  EXPECT_NE(d.find("graphs/rock.json"), std::string::npos);
  for (const auto& name : listFiles(dir.path() / "out")) EXPECT_NE(d.find(name), std::string::npos) << name;
  // One rule per material.
  EXPECT_EQ(std::count(d.begin(), d.end(), ':'), 2);
}

TEST(Batch, FailedBatchWritesNoDepfileAndNoOutputs) {
  TempDir dir("depfile-bad");
  fs::path depfile = dir.path() / "out.d";
  auto r = runCommand(shellQuote(WG_CLI_PATH) + " compile " + shellQuote(std::string(WG_SOURCE_DIR) + "/graphs/rock.json") +
                      " " + shellQuote(std::string(WG_SOURCE_DIR) + "/tests/bad/WG2001_unknown-op.json") + " -j2 --depfile " +
                      shellQuote(depfile.string()) + " -o " + shellQuote((dir.path() / "out").string()));
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_FALSE(fs::exists(depfile));
  EXPECT_TRUE(listFiles(dir.path()).empty());
}

// Each graph is valid alone; the command line put two that write the same files together.
TEST(Batch, TwoMaterialsOfOneNameAreAUsageError) {
  TempDir dir("same-name");
  for (const char* folder : {"a", "b"}) {
    fs::create_directories(dir.path() / folder);
    testing::writeFile(dir.path() / folder / "g.json", R"({"name": "lit", "nodes": [], "output": {"roughness": 0.4}})");
  }
  auto r = runCommand(shellQuote(WG_CLI_PATH) + " compile " + shellQuote((dir.path() / "a" / "g.json").string()) + " " +
                      shellQuote((dir.path() / "b" / "g.json").string()) + " -o " + shellQuote((dir.path() / "out").string()));
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("WG2020"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir.path() / "out"));
}

TEST(Batch, JobCountIsValidated) {
  auto r = runCommand(shellQuote(WG_CLI_PATH) + " compile " + shellQuote(std::string(WG_SOURCE_DIR) + "/graphs/rock.json") +
                      " -j0 -o /tmp/never");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.output.find("WG9001"), std::string::npos);
}

}  // namespace
}  // namespace wg
