// Loader and IR-builder rules that have no single catalog file: regressions for bugs
// found in review.
#include <gtest/gtest.h>

#include "driver/material_compiler.hpp"
#include "ir_fixture.hpp"

namespace wg {
namespace {

std::vector<DiagCode> codesFor(const std::string& json) {
  DiagnosticList d;
  (void)buildOptimizedIr("t.json", json, d);
  std::vector<DiagCode> codes;
  for (const auto& item : d.items()) codes.push_back(item.code);
  return codes;
}

TEST(GraphValidation, MixedSwizzleSetsAreRejectedNotMiscompiled) {
  auto codes = codesFor(testing::graphJson(
      R"({"id": "uv", "op": "texcoord"}, {"id": "s", "op": "swizzle", "inputs": {"in": "uv.out", "channels": "xg"}})",
      R"("roughness": "s.out")"));
  EXPECT_EQ(codes, std::vector<DiagCode>{DiagCode::SwizzleMismatch});
  EXPECT_TRUE(codesFor(testing::graphJson(
                           R"({"id": "uv", "op": "texcoord"}, {"id": "s", "op": "swizzle", "inputs": {"in": "uv.out", "channels": "g"}})",
                           R"("roughness": "s.out")"))
                  .empty());
}

TEST(GraphValidation, OverflowingNumbersAreNotFiniteLiterals) {
  auto codes = codesFor(R"({"name": "t", "nodes": [], "output": {"roughness": 1e999}})");
  EXPECT_EQ(codes, std::vector<DiagCode>{DiagCode::LiteralNotFinite});
}

// The error points at the number itself, by line, column and pointer, even where a
// string before it spells the same digits.
TEST(GraphValidation, AnOverflowingNumberIsLocatedWhereItIs) {
  DiagnosticList d;
  (void)buildOptimizedIr("t.json", "{\"name\": \"1e999\",\n \"nodes\": [], \"output\": {\"roughness\": 1e999}}", d);
  ASSERT_EQ(d.items().size(), 1u);
  EXPECT_EQ(d.items()[0].code, DiagCode::LiteralNotFinite);
  EXPECT_EQ(d.items()[0].location.pointer, "/output/roughness");
  EXPECT_EQ(d.items()[0].location.line, 2);
  EXPECT_EQ(d.items()[0].location.column, 39);
}

TEST(GraphValidation, BoolParametersHaveNoRange) {
  auto codes = codesFor(R"({"name": "t", "parameters": {"b": {"type": "bool", "default": true, "min": 0}},
                            "nodes": [], "output": {}})");
  EXPECT_EQ(codes, std::vector<DiagCode>{DiagCode::BoolParameterRange});
}

TEST(GraphValidation, MinAboveMaxIsOneError) {
  auto codes = codesFor(R"({"name": "t", "parameters": {"a": {"type": "float", "default": 0.5, "min": 1, "max": 0}},
                            "nodes": [], "output": {}})");
  EXPECT_EQ(codes, std::vector<DiagCode>{DiagCode::ParameterRangeInverted});
}

TEST(GraphValidation, IntegralFloatsAreIntegers) {
  auto codes = codesFor(R"({"name": "t", "textures": {"t": {"generator": "fbm", "seed": 3.0, "size": 64.0}},
                            "nodes": [], "output": {}})");
  EXPECT_TRUE(codes.empty());
  codes = codesFor(R"({"name": "t", "textures": {"t": {"generator": "fbm", "seed": 3.5}}, "nodes": [], "output": {}})");
  EXPECT_EQ(codes, std::vector<DiagCode>{DiagCode::InvalidGeneratorOption});
}

TEST(GraphValidation, DescriptionsMustBeStrings) {
  auto codes = codesFor(R"({"name": "t", "description": 3, "nodes": [], "output": {}})");
  EXPECT_EQ(codes, std::vector<DiagCode>{DiagCode::WrongJsonKind});
}

TEST(GraphValidation, ForwardReferencesResolve) {
  EXPECT_TRUE(codesFor(testing::graphJson(
                           R"({"id": "later", "op": "split", "inputs": {"in": "first.out"}}, {"id": "first", "op": "world_position"})",
                           R"("roughness": "later.y")"))
                  .empty());
}

}  // namespace
}  // namespace wg
