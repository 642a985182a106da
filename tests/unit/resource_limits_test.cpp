// Every resource limit (issue 6, hardening) stops the compile with WG1007 and nothing else.
#include <gtest/gtest.h>
#include <stb_image_write.h>

#include <filesystem>
#include <fstream>

#include "compiler/material_compiler.hpp"
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

}  // namespace
}  // namespace wg
