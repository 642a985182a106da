// Source locations for JSON pointers, duplicate keys, limits and syntax errors.
#include <gtest/gtest.h>

#include "compiler/json_document.hpp"

namespace wg {
namespace {

TEST(JsonDocument, LocatesEveryPointer) {
  std::string text = "{\n  \"a\": [1,\n    {\"b/c\": true}],\n  \"caf\xc3\xa9\": \"x\"\n}";
  DiagnosticList d;
  auto doc = parseJsonDocument("f.json", text, d);
  ASSERT_TRUE(doc);
  auto at = [&](const std::string& p) {
    auto loc = doc->locate(p);
    return std::make_pair(loc.line, loc.column);
  };
  EXPECT_EQ(at(""), std::make_pair(1, 1));
  EXPECT_EQ(at("/a"), std::make_pair(2, 8));
  EXPECT_EQ(at("/a/0"), std::make_pair(2, 9));
  EXPECT_EQ(at("/a/1"), std::make_pair(3, 5));
  EXPECT_EQ(at("/a/1/b~1c"), std::make_pair(3, 13));
  EXPECT_EQ(at("/caf\xc3\xa9"), std::make_pair(4, 11));  // columns count code points
  EXPECT_EQ(at("/a/1/missing"), std::make_pair(3, 5));  // nearest located ancestor
}

TEST(JsonDocument, ReportsSyntaxErrorsWithLineAndColumn) {
  DiagnosticList d;
  EXPECT_FALSE(parseJsonDocument("f.json", "{\n  \"a\": 1,\n  \"b\": ]\n}", d));
  ASSERT_EQ(d.items().size(), 1u);
  EXPECT_EQ(d.items()[0].code, DiagCode::JsonSyntax);
  EXPECT_EQ(d.items()[0].location.line, 3);
}

TEST(JsonDocument, RejectsDuplicateKeys) {
  DiagnosticList d;
  EXPECT_FALSE(parseJsonDocument("f.json", R"({"a": 1, "b": {"x": 1, "x": 2}})", d));
  ASSERT_EQ(d.items().size(), 1u);
  EXPECT_EQ(d.items()[0].code, DiagCode::DuplicateKey);
  EXPECT_EQ(d.items()[0].location.pointer, "/b/x");
}

TEST(JsonDocument, NamesNestedDuplicatesByPointer) {
  DiagnosticList d;
  EXPECT_FALSE(parseJsonDocument("f.json", R"({"nodes": [{"a": 1}, {"id": 1, "x": {"k": 0}, "id": 2}]})", d));
  ASSERT_EQ(d.items().size(), 1u);
  EXPECT_EQ(d.items()[0].location.pointer, "/nodes/1/id");
}

TEST(JsonDocument, EnforcesDepthAndSizeLimits) {
  DiagnosticList d;
  std::string deep(100000, '[');
  EXPECT_FALSE(parseJsonDocument("f.json", deep, d));
  EXPECT_TRUE(d.contains(DiagCode::ResourceLimit));
  DiagnosticList d2;
  JsonLimits small;
  small.maxBytes = 10;
  EXPECT_FALSE(parseJsonDocument("f.json", R"({"name": "long enough"})", d2, small));
  EXPECT_TRUE(d2.contains(DiagCode::ResourceLimit));
}

TEST(JsonPointer, EscapesTokens) {
  EXPECT_EQ(appendPointer("/a", "b/c~d"), "/a/b~1c~0d");
  EXPECT_EQ(appendPointer("", std::size_t{3}), "/3");
}

}  // namespace
}  // namespace wg
