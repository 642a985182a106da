// Every resource limit stops the compile with WG1007 and nothing else.
#include <gtest/gtest.h>
#include <stb_image_write.h>

#include <filesystem>
#include <fstream>

#include "compiler/constant_count.hpp"
#include "driver/material_compiler.hpp"
#include "ir_fixture.hpp"
#include "nodes/image_file.hpp"

namespace wg {
namespace {

std::vector<DiagCode> codesOf(const DiagnosticList& d) {
  std::vector<DiagCode> codes;
  for (const auto& item : d.items()) codes.push_back(item.code);
  return codes;
}

// A chain texcoord -> n1 -> ... -> n<links> feeding roughness: depth links + 1.
std::string chainGraph(int links) {
  std::string nodes = R"({"id": "n0", "op": "texcoord"}, {"id": "x", "op": "swizzle", "inputs": {"in": "n0.out", "channels": "x"}})";
  std::string previous = "x";
  for (int i = 1; i <= links; ++i) {
    std::string id = "n" + std::to_string(i);
    nodes += R"(, {"id": ")" + id + R"(", "op": "one_minus", "inputs": {"in": ")" + previous + R"(.out"}})";
    previous = id;
  }
  return testing::graphJson(nodes, R"("roughness": ")" + previous + R"(.out")");
}

TEST(ResourceLimits, GraphDepthAtTheLimitCompiles) {
  DiagnosticList d;
  // texcoord + swizzle + 4094 links = a chain of exactly 4096 nodes.
  EXPECT_TRUE(buildOptimizedIr("deep.json", chainGraph(4094), d).has_value());
  EXPECT_TRUE(d.items().empty());
}

TEST(ResourceLimits, GraphDepthOverTheLimitNamesTheDeepestNode) {
  DiagnosticList d;
  EXPECT_FALSE(buildOptimizedIr("deep.json", chainGraph(4095), d).has_value());
  ASSERT_EQ(codesOf(d), std::vector<DiagCode>{DiagCode::ResourceLimit});
  const Diagnostic& diag = d.items().front();
  EXPECT_EQ(diag.location.pointer, "/nodes/4096");  // n4095, where the over-long chain ends
  EXPECT_NE(diag.message.find("'n4095'"), std::string::npos) << diag.message;
  EXPECT_NE(diag.message.find("4097"), std::string::npos) << diag.message;
}

// `count` unlinked texcoord nodes (each of depth 1) through buildIr with `limits`.
bool buildWideGraph(int count, const IrLimits& limits, DiagnosticList& d) {
  std::string nodes;
  for (int i = 0; i < count; ++i) nodes += (i ? ", " : "") + std::string(R"({"id": "t)") + std::to_string(i) + R"(", "op": "texcoord"})";
  auto document = parseJsonDocument("wide.json", testing::graphJson(nodes, ""), d);
  auto graph = document ? loadMaterialGraph(*document, d) : std::nullopt;
  EXPECT_TRUE(graph) << "the wide graph itself must load";
  return graph && buildIr(*graph, *document, d, IrBuildOptions{.limits = limits}).has_value();
}

TEST(ResourceLimits, DepthCountsTheLongestPathNotTheNodeCount) {
  // 300 independent nodes of depth 1 and a graph limit of 2: wide graphs are fine.
  DiagnosticList d;
  EXPECT_TRUE(buildWideGraph(300, IrLimits{.maxDepth = 2}, d));
  EXPECT_TRUE(d.items().empty());
}

TEST(ResourceLimits, NodeCountOverTheLimitIsOneError) {
  DiagnosticList d;
  EXPECT_FALSE(buildWideGraph(5, IrLimits{.maxNodes = 4}, d));
  ASSERT_EQ(codesOf(d), std::vector<DiagCode>{DiagCode::ResourceLimit});
  EXPECT_EQ(d.items().front().location.pointer, "/nodes");
  EXPECT_NE(d.items().front().message.find("node count"), std::string::npos);
}

TEST(ResourceLimits, ParameterCountOverTheLimitIsAnInputErrorNotAnInternalOne) {
  auto graphWith = [](int count) {
    nlohmann::json g = {{"name", "many"}, {"nodes", nlohmann::json::array()}, {"output", nlohmann::json::object()}};
    for (int i = 0; i < count; ++i) g["parameters"]["p" + std::to_string(i)] = {{"type", "float"}, {"default", 0.5}};
    return g.dump();
  };
  CompileOptions noSpirv{.emitSpirv = false};
  EXPECT_TRUE(compileMaterialText("many.json", graphWith(1024), noSpirv).material.has_value());
  CompileResult over = compileMaterialText("many.json", graphWith(1025), noSpirv);
  EXPECT_FALSE(over.material.has_value());
  ASSERT_EQ(codesOf(over.diagnostics), std::vector<DiagCode>{DiagCode::ResourceLimit});
  EXPECT_EQ(over.diagnostics.items().front().location.pointer, "/parameters");
}

class ResourceLimitFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("wg-limits-" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  std::filesystem::path dir_;
};

TEST_F(ResourceLimitFiles, OversizedGraphFileIsRefusedBeforeReading) {
  {
    std::ofstream out(path("huge.json"), std::ios::binary);
    out << R"({"name": "t", "nodes": [], "output": {}, "description": ")";
    out << std::string(JsonLimits{}.maxBytes, 'a') << "\"}";
  }
  CompileOptions options;
  CompileResult result = compileMaterialFile(path("huge.json"), options);
  ASSERT_EQ(codesOf(result.diagnostics), std::vector<DiagCode>{DiagCode::ResourceLimit});
  EXPECT_EQ(result.diagnostics.items().front().location.file, path("huge.json"));
  EXPECT_NE(result.diagnostics.items().front().message.find("file size"), std::string::npos);
}

TEST_F(ResourceLimitFiles, OversizedTextureFileIsResourceLimitAtItsPointer) {
  const int wide = kMaxImageFileDimension + 1;
  const std::vector<std::uint8_t> row(static_cast<std::size_t>(wide), 0);
  ASSERT_TRUE(stbi_write_png(path("wide.png").c_str(), wide, 1, 1, row.data(), wide));
  std::ofstream(path("m.json")) << R"({"name": "t", "textures": {"big": {"file": "wide.png"}},
    "nodes": [{"id": "uv", "op": "texcoord"}, {"id": "s", "op": "sample", "inputs": {"texture": "big", "uv": "uv.out"}}],
    "output": {"baseColor": "s.rgb"}})";
  CompileOptions options;
  CompileResult result = compileMaterialFile(path("m.json"), options);
  ASSERT_EQ(codesOf(result.diagnostics), std::vector<DiagCode>{DiagCode::ResourceLimit});
  EXPECT_EQ(result.diagnostics.items().front().location.pointer, "/textures/big/file");
  EXPECT_NE(result.diagnostics.items().front().message.find("8192"), std::string::npos);
}


// A header claiming 60000x60000 pixels is a size limit, reported with the image's file,
// before anything is decoded (stb alone calls it "unknown image type").
TEST_F(ResourceLimitFiles, PngBombIsResourceLimitNamingTheFile) {
  const std::uint8_t header[] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n', 0, 0, 0, 13, 'I', 'H', 'D', 'R',
                                 0, 0, 0xEA, 0x60, 0, 0, 0xEA, 0x60, 8, 6, 0, 0, 0, 0, 0, 0, 0};
  std::ofstream(path("bomb.png"), std::ios::binary).write(reinterpret_cast<const char*>(header), sizeof header);
  std::ofstream(path("m.json")) << R"({"name": "t", "textures": {"big": {"file": "bomb.png"}},
    "nodes": [{"id": "uv", "op": "texcoord"}, {"id": "s", "op": "sample", "inputs": {"texture": "big", "uv": "uv.out"}}],
    "output": {"baseColor": "s.rgb"}})";
  CompileResult result = compileMaterialFile(path("m.json"), CompileOptions{});
  ASSERT_EQ(codesOf(result.diagnostics), std::vector<DiagCode>{DiagCode::ResourceLimit});
  const Diagnostic& d = result.diagnostics.items().front();
  EXPECT_EQ(d.location.pointer, "/textures/big/file");
  EXPECT_GT(d.location.line, 0);
  EXPECT_NE(d.message.find("bomb.png"), std::string::npos) << d.message;
  EXPECT_NE(d.message.find("60000x60000"), std::string::npos) << d.message;
}

// Each library is within the file limit, but the includes together are limited too.
TEST_F(ResourceLimitFiles, IncludeCountIsLimited) {
  std::ofstream(path("lib.json")) << R"({"parameters": {"k": {"type": "float", "default": 0.5}}})";
  std::string includes;
  for (int i = 0; i < 65; ++i) includes += std::string(i ? ", " : "") + "\"a" + std::to_string(i) + "\": \"lib.json\"";
  std::ofstream(path("m.json")) << R"({"name": "t", "include": {)" + includes + R"(}, "nodes": [], "output": {}})";
  CompileResult result = compileMaterialFile(path("m.json"), CompileOptions{});
  ASSERT_EQ(codesOf(result.diagnostics), std::vector<DiagCode>{DiagCode::ResourceLimit});
  EXPECT_EQ(result.diagnostics.items().front().location.pointer, "/include");
}

TEST_F(ResourceLimitFiles, IncludedBytesTogetherAreLimitedBeforeReading) {
  {
    std::ofstream lib(path("lib.json"), std::ios::binary);
    lib << R"({"description": ")" << std::string(12u << 20, 'a') << R"(", "nodes": []})";
  }
  std::ofstream(path("m.json")) << R"({"name": "t", "include": {"a": "lib.json", "b": "lib.json", "c": "lib.json", "d": "lib.json"},
    "nodes": [], "output": {}})";
  CompileResult result = compileMaterialFile(path("m.json"), CompileOptions{});
  ASSERT_EQ(codesOf(result.diagnostics), std::vector<DiagCode>{DiagCode::ResourceLimit});
  EXPECT_EQ(result.diagnostics.items().front().location.pointer, "/include/c");  // 3 x 12 MiB > 32 MiB
}

// glslang's cost grows with the square of distinct constants, so they are limited after
// folding: 8,192 compile in about two seconds, 20,000 took eight.
TEST(ResourceLimits, DistinctConstantsAreLimitedAfterFolding) {
  // `constants` leaves u + c_i, each c_i distinct, reduced by a balanced tree of max.
  auto graphWith = [](int constants) {
    std::string nodes = R"({"id": "uv", "op": "texcoord"}, {"id": "u", "op": "swizzle", "inputs": {"in": "uv.out", "channels": "x"}})";
    std::vector<std::string> level;
    for (int i = 0; i < constants; ++i) {
      level.push_back("n" + std::to_string(i));
      nodes += R"(, {"id": ")" + level.back() + R"(", "op": "add", "inputs": {"a": "u.out", "b": )" + std::to_string(1 + i) + "}}";
    }
    for (int round = 0; level.size() > 1; ++round) {
      std::vector<std::string> next;
      for (std::size_t i = 0; i + 1 < level.size(); i += 2) {
        next.push_back("r" + std::to_string(round) + "_" + std::to_string(i));
        nodes += R"(, {"id": ")" + next.back() + R"(", "op": "max", "inputs": {"a": ")" + level[i] + R"(.out", "b": ")" +
                 level[i + 1] + R"(.out"}})";
      }
      if (level.size() % 2) next.push_back(level.back());
      level = next;
    }
    return testing::graphJson(nodes, R"("roughness": ")" + level.front() + R"(.out")");
  };
  CompileOptions options;
  options.emitSpirv = false;
  CompileResult within = compileMaterialText("m.json", graphWith(4000), options);
  EXPECT_TRUE(within.material);
  CompileResult over = compileMaterialText("m.json", graphWith(static_cast<int>(kMaxDistinctConstants)), options);
  ASSERT_EQ(codesOf(over.diagnostics), std::vector<DiagCode>{DiagCode::ResourceLimit});
  EXPECT_EQ(over.diagnostics.items().front().location.pointer, "/nodes");
}

}  // namespace
}  // namespace wg
