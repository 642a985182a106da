// The fast JSON front end against nlohmann's own parser: the same DOM, value for value
// and type for type, or a false that hands the text back to nlohmann.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "compiler/json_reader.hpp"

namespace wg {
namespace {

std::optional<nlohmann::json> fastDom(const std::string& text) {
  nlohmann::json root;
  JsonDomBuilder builder(root);
  if (!readJsonEvents(text, builder)) return std::nullopt;
  return root;
}

std::optional<nlohmann::json> nlohmannDom(const std::string& text) {
  nlohmann::json root = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (root.is_discarded()) return std::nullopt;
  return root;
}

// dump() tells 1 from 1.0 and 0 from -0.0, which operator== does not.
std::string typed(const nlohmann::json& value) { return value.dump(); }

std::string readFile(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(JsonReader, ReadsEveryRealFileAsNlohmannDoes) {
  std::vector<std::filesystem::path> files;
  for (const char* dir : {"graphs", "tests/bad", "timelines", "examples"})
    for (const auto& entry : std::filesystem::recursive_directory_iterator(std::string(WG_SOURCE_DIR) + "/" + dir))
      if (entry.path().extension() == ".json") files.push_back(entry.path());
  // glTF files nobody here wrote (Debian's assimp-testmodels).
  const std::filesystem::path gltf = "/usr/share/assimp/models/glTF2";
  if (std::filesystem::exists(gltf))
    for (const auto& entry : std::filesystem::recursive_directory_iterator(gltf))
      if (entry.path().extension() == ".gltf") files.push_back(entry.path());
  ASSERT_GT(files.size(), 60u);
  std::size_t fast = 0;
  for (const auto& path : files) {
    std::string text = readFile(path);
    if (text.find('\0') != std::string::npos) continue;  // refused before either reader runs
    auto expected = nlohmann::json::accept(text) ? nlohmannDom(text) : std::nullopt;
    auto got = fastDom(text);
    if (!expected) {
      EXPECT_FALSE(got) << path;
      continue;
    }
    if (got) {
      ++fast;
      EXPECT_TRUE(typed(*got) == typed(*expected)) << path;
    }
    // Every bundled graph takes the fast path, or the speed-up is gone.
    if (path.parent_path().filename() == "graphs") {
      EXPECT_TRUE(got) << path;
    }
  }
  EXPECT_GT(fast, files.size() / 2);
}

TEST(JsonReader, AgreesOnEdgeCasesOrHandsThemBack) {
  const std::vector<std::string> cases = {
      "0", "-0", "1", "-1", "0.1", "-0.0", "1E2", "1e+2", "1e-2", "5e-324", "1.7976931348623157e308", "1e400", "1e-400",
      "-9223372036854775808", "-9223372036854775809", "18446744073709551615", "18446744073709551616",
      "123456789012345678901234567890", "01", "+1", ".5", "1.", "-", "NaN", "Infinity", "true", "null", "\"x\"",
      "{}", "[]", " \n[1] \n", "[1,]", "{\"a\":1,}", "[] []", "{\"a\":1,\"a\":2}", "{\"a\" 1}", "[1 2]", "",
      " ", "\"\\u0000\"", "\"\\ud800\"", "\"\\udc00\"", "\"\\ud800x\"", "\"\\ud83d\\ude00\"", "\"\xc3\xa9\"",
      "\"\xff\"", "\"\xc0\xaf\"", "\"\xed\xa0\x80\"", "\"\xf4\x90\x80\x80\"", "\"\t\"", "\"\\x\"",
      "\"\\/\\b\\f\\n\\r\\t\\\"\\\\\"", "\xEF\xBB\xBF{}", "{\"\\ud800\": 1}", "[[[[1]]]]", "{\"a\":[1,{\"b\":null}]}",
      "// c\n{}", "{'a':1}", "[1e5, -1E-5, 2.5e-3]"};
  for (const std::string& text : cases) {
    auto expected = nlohmannDom(text);
    auto got = fastDom(text);
    if (!expected) {
      EXPECT_FALSE(got) << text;
    } else if (got) {
      EXPECT_EQ(typed(*got), typed(*expected)) << text;
    }
  }
  // The common cases must not fall back.
  for (const char* text : {"-0", "18446744073709551616", "-9223372036854775809", "\"\\ud83d\\ude00\"", "{\"a\":1,\"a\":2}"})
    EXPECT_TRUE(fastDom(text)) << text;
}

TEST(JsonReader, HandsBackTextNestedTooDeep) {
  nlohmann::json root;
  JsonDomBuilder builder(root);
  EXPECT_TRUE(readJsonEvents("[[[1]]]", builder, 3));
  nlohmann::json deeper;
  JsonDomBuilder deeperBuilder(deeper);
  EXPECT_FALSE(readJsonEvents("[[[[1]]]]", deeperBuilder, 3));
}

TEST(JsonReader, CountsKeysSoDuplicatesShow) {
  nlohmann::json root;
  JsonDomBuilder builder(root);
  ASSERT_TRUE(readJsonEvents(R"({"a": 1, "b": {"c": 2, "c": 3}})", builder));
  EXPECT_EQ(builder.keysRead(), 4u);
  EXPECT_EQ(root["b"].size(), 1u);
}

}  // namespace
}  // namespace wg
