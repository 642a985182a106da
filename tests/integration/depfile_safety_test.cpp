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
  EXPECT_NE(r.output.find("WG3003"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir.path() / "out"));
}

}  // namespace
