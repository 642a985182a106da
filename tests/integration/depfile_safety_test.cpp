// Paths from a graph reach the depfile and the file system: a newline and a tab in a
// texture name would start a Make recipe line, and a NUL would make the loader read
// another file than the graph names. Both stop the run before anything is written.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "process_support.hpp"

namespace {

namespace fs = std::filesystem;
using wg::testing::runCommand;
using wg::testing::shellQuote;
using wg::testing::TempDir;
using wg::testing::writeFile;

// A graph whose one texture is `file` (JSON-escaped), beside a real PNG of that name.
void writeGraphWithTexture(const fs::path& dir, const std::string& jsonFileName) {
  writeFile(dir / "g.json", R"({"name": "g", "textures": {"t": {"file": ")" + jsonFileName + R"("}},
    "nodes": [{"id": "uv", "op": "texcoord"}, {"id": "s", "op": "sample", "inputs": {"texture": "t", "uv": "uv.out"}}],
    "output": {"baseColor": "s.rgb"}})");
}

std::string anyPng() {
  for (const auto& e : fs::recursive_directory_iterator(fs::path(WG_SOURCE_DIR) / "examples"))
    if (e.path().extension() == ".png") return e.path().string();
  return "";
}

TEST(DepfileSafety, NewlineAndTabInATextureNameStopTheDepfileBeforeAnythingIsWritten) {
  TempDir dir("wg-depfile-safety");
  std::string png = anyPng();
  ASSERT_FALSE(png.empty()) << "no PNG under examples/";
  fs::copy_file(png, dir.path() / "g\n\ttouch PWNED.png");
  writeGraphWithTexture(dir.path(), "g\\n\\ttouch PWNED.png");
  fs::path out = dir.path() / "out", depfile = dir.path() / "out.d";
  auto r = runCommand(shellQuote(WG_CLI_PATH) + " compile " + shellQuote((dir.path() / "g.json").string()) + " -o " +
                      shellQuote(out.string()) + " --depfile " + shellQuote(depfile.string()));
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("depfile"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(out)) << "outputs were written before the depfile was refused";
  EXPECT_FALSE(fs::exists(depfile));
  EXPECT_EQ(r.output.find('\t'), std::string::npos) << "the raw tab reached the terminal";
  // The same graph compiles without a depfile: the name is fine for the file system.
  auto plain = runCommand(shellQuote(WG_CLI_PATH) + " compile " + shellQuote((dir.path() / "g.json").string()) + " -o " +
                          shellQuote(out.string()) + " --target glsl");
  EXPECT_EQ(plain.exitCode, 0) << plain.output;
}

TEST(DepfileSafety, NulInsideATexturePathIsRejected) {
  TempDir dir("wg-depfile-safety");
  std::string png = anyPng();
  ASSERT_FALSE(png.empty());
  fs::copy_file(png, dir.path() / "ok.png");
  writeGraphWithTexture(dir.path(), "ok.png\\u0000.txt");
  auto r = runCommand(shellQuote(WG_CLI_PATH) + " compile " + shellQuote((dir.path() / "g.json").string()) + " -o " +
                      shellQuote((dir.path() / "out").string()) + " --diagnostics json");
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_NE(r.output.find("WG1002"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir.path() / "out"));
}

}  // namespace

namespace {

std::string compileCommand(const fs::path& graph, const fs::path& out, const std::string& extra = "") {
  return shellQuote(WG_CLI_PATH) + " compile " + shellQuote(graph.string()) + " -o " + shellQuote(out.string()) + extra;
}

fs::path bundledRock() { return fs::path(WG_SOURCE_DIR) / "graphs" / "rock.json"; }

TEST(CompileAllOrNothing, DepfileNamingADirectoryOrAMissingFolderWritesNothing) {
  TempDir dir("wg-all-or-nothing");
  fs::create_directory(dir.path() / "taken");
  for (const fs::path& depfile : {dir.path() / "taken", dir.path() / "missing" / "out.d"}) {
    auto r = runCommand(compileCommand(bundledRock(), dir.path() / "out", " --depfile " + shellQuote(depfile.string())));
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_FALSE(fs::exists(dir.path() / "out")) << depfile << ": outputs were written before the depfile failed";
  }
}

TEST(CompileAllOrNothing, AnOutputNameTakenByADirectoryWritesNothingElse) {
  TempDir dir("wg-all-or-nothing");
  fs::create_directories(dir.path() / "out" / "rock.reflect.json");
  auto r = runCommand(compileCommand(bundledRock(), dir.path() / "out"));
  EXPECT_EQ(r.exitCode, 2) << r.output;
  std::vector<std::string> left;
  for (const auto& e : fs::directory_iterator(dir.path() / "out")) left.push_back(e.path().filename().string());
  EXPECT_EQ(left, std::vector<std::string>{"rock.reflect.json"}) << "a failed run left files behind";
}

TEST(CompileAllOrNothing, InputsAreNeverOutputs) {
  TempDir dir("wg-all-or-nothing");
  fs::copy_file(bundledRock(), dir.path() / "rock.json");
  const std::string graph = wg::testing::readFile(dir.path() / "rock.json");
  auto r = runCommand(compileCommand(dir.path() / "rock.json", dir.path() / "out", " --depfile " + shellQuote((dir.path() / "rock.json").string())));
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_EQ(wg::testing::readFile(dir.path() / "rock.json"), graph) << "--depfile replaced the input graph";
  // A graph named like an output, compiled into its own folder.
  std::string renamed = graph;
  fs::copy_file(bundledRock(), dir.path() / "x.reflect.json");
  wg::testing::writeFile(dir.path() / "x.reflect.json", renamed.replace(renamed.find("\"name\": \"rock\""), 14, "\"name\": \"x\""));
  const std::string before = wg::testing::readFile(dir.path() / "x.reflect.json");
  r = runCommand(compileCommand(dir.path() / "x.reflect.json", dir.path()));
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_EQ(wg::testing::readFile(dir.path() / "x.reflect.json"), before) << "the reflection replaced its own graph";
}

}  // namespace
