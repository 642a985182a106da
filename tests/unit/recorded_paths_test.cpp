// Outputs record texture paths relative to the graph, never absolute: a build cache
// keyed on the reflection must not depend on where the checkout lives.
#include <gtest/gtest.h>
#include <stb_image_write.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "driver/material_compiler.hpp"

namespace wg {
namespace {

std::string recordedFile(const std::filesystem::path& graph, const std::string& written) {
  std::ofstream(graph) << R"({"name": "t", "textures": {"albedo": {"file": ")" + written + R"("}},
    "nodes": [{"id": "uv", "op": "texcoord"}, {"id": "s", "op": "sample", "inputs": {"texture": "albedo", "uv": "uv.out"}}],
    "output": {"baseColor": "s.rgb"}})";
  CompileOptions options;
  options.emitSpirv = false;
  CompileResult result = compileMaterialFile(graph.string(), options);
  EXPECT_TRUE(result.material);
  if (!result.material) return "";
  auto reflection = nlohmann::json::parse(result.material->reflectionJson);
  return reflection["textures"][0]["source"]["file"].get<std::string>();
}

class RecordedPaths : public ::testing::Test {
 protected:
  void SetUp() override {
    // One folder per test: ctest runs the tests of this fixture in parallel processes.
    dir_ = std::filesystem::temp_directory_path() /
           ("wg-recorded-paths-" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_ / "graphs");
    std::filesystem::create_directories(dir_ / "images");
    const std::uint8_t texels[16 * 16 * 4] = {};
    ASSERT_TRUE(stbi_write_png((dir_ / "images" / "a.png").c_str(), 16, 16, 4, texels, 16 * 4));
  }
  void TearDown() override {
    std::filesystem::remove_all(dir_);
    std::filesystem::remove_all(dir_.string() + "-moved");
  }
  std::filesystem::path dir_;
};

TEST_F(RecordedPaths, AbsoluteTexturePathIsRecordedRelativeToTheGraph) {
  const std::string absolute = (dir_ / "images" / "a.png").string();
  const std::string recorded = recordedFile(dir_ / "graphs" / "m.json", absolute);
  EXPECT_EQ(recorded, "../images/a.png");
}

TEST_F(RecordedPaths, RelativeTexturePathIsRecordedAsWritten) {
  EXPECT_EQ(recordedFile(dir_ / "graphs" / "m.json", "../images/./a.png"), "../images/a.png");
}

TEST_F(RecordedPaths, TheSameMaterialRecordsTheSamePathWhereverItLives) {
  const std::string first = recordedFile(dir_ / "graphs" / "m.json", (dir_ / "images" / "a.png").string());
  std::filesystem::rename(dir_, dir_.string() + "-moved");
  const std::filesystem::path moved = dir_.string() + "-moved";
  const std::string second = recordedFile(moved / "graphs" / "m.json", (moved / "images" / "a.png").string());
  std::filesystem::rename(moved, dir_);
  EXPECT_EQ(first, second);
}

}  // namespace
}  // namespace wg
