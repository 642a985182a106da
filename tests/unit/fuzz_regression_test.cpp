// Every input in tests/fuzz/regressions goes through its fuzz target's path and must
// come back as diagnostics or a result, never a crash or a broken property (ASan/UBSan
// in CI check the rest): graphs (with their libraries) at the top, timelines in
// timeline/, command-line arguments in cli_options/.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "driver/material_compiler.hpp"
#include "tests/fuzz/cli_options_case.hpp"
#include "tests/fuzz/graph_with_libraries.hpp"
#include "tests/fuzz/timeline_case.hpp"

namespace wg {
namespace {

namespace fs = std::filesystem;

const fs::path kRegressions = fs::path(WG_SOURCE_DIR) / "tests/fuzz/regressions";

std::string readFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// The regular files of `dir` with `extension` ("" for any), sorted for stable output.
std::vector<fs::path> casesIn(const fs::path& dir, const std::string& extension) {
  std::vector<fs::path> cases;
  for (const auto& entry : fs::directory_iterator(dir))
    if (entry.is_regular_file() && (extension.empty() || entry.path().extension() == extension) &&
        entry.path().filename() != "README.md")
      cases.push_back(entry.path());
  std::sort(cases.begin(), cases.end());
  return cases;
}

class FuzzRegressions : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = fuzz::makeFuzzDirectory(); }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  fs::path dir_;
};

TEST_F(FuzzRegressions, EveryGraphCompilesOrFailsCleanly) {
  std::size_t cases = 0;
  for (const auto& path : casesIn(kRegressions, ".json")) {
    CompileResult r = fuzz::compileGraphWithLibraries(readFile(path), dir_);
    EXPECT_TRUE(r.material.has_value() != r.diagnostics.hasErrors()) << path;
    if (r.material) {
      EXPECT_EQ(r.material->stages.size(), 4u) << path;
    }
    ++cases;
  }
  EXPECT_GE(cases, 4u);
}

// The fuzz input format really puts libraries on disk where the graph includes them.
TEST_F(FuzzRegressions, GraphLibrariesAreIncludedFromTheInput) {
  CompileResult r = fuzz::compileGraphWithLibraries(readFile(kRegressions / "library-stone.json"), dir_);
  ASSERT_TRUE(r.material) << (r.diagnostics.empty() ? "" : formatDiagnosticText(r.diagnostics.items().front()));
  EXPECT_EQ(r.material->ir.includedFiles, std::vector<std::string>{(dir_ / "lib1.json").string()});
  // A later input without libraries must not see the earlier one's.
  r = fuzz::compileGraphWithLibraries(readFile(kRegressions / "library-stone.json").substr(0, 40), dir_);
  EXPECT_FALSE(fs::exists(dir_ / "lib1.json"));
}

TEST(FuzzRegressionInputs, SplitAtTheLibrarySeparator) {
  auto parts = fuzz::splitGraphInput("{}\n---\nA\n---\n\n---\nC\n---\nD\n---\nE");
  EXPECT_EQ(parts.graph, "{}");
  EXPECT_EQ(parts.libraries, (std::vector<std::string>{"A", "", "C", "D"}));
  EXPECT_TRUE(fuzz::splitGraphInput("{}").libraries.empty());
}

TEST(FuzzRegressionInputs, EveryTimelineLoadsOrFailsCleanly) {
  std::size_t cases = 0;
  for (const auto& path : casesIn(kRegressions / "timeline", "")) {
    EXPECT_EQ(fuzz::checkTimelineInput(readFile(path)), "") << path;
    ++cases;
  }
  EXPECT_GE(cases, 1u);
}

TEST(FuzzRegressionInputs, EveryCommandLineParsesOrFailsCleanly) {
  std::size_t cases = 0;
  for (const auto& path : casesIn(kRegressions / "cli_options", "")) {
    EXPECT_EQ(fuzz::checkCliOptionsInput(readFile(path)), "") << path;
    ++cases;
  }
  EXPECT_GE(cases, 1u);
}

}  // namespace
}  // namespace wg
