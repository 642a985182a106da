// A stage emits the library functions it reaches and no others.
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <set>
#include <sstream>

#include "backends/derived_hlsl.hpp"
#include "backends/library_functions.hpp"
#include "driver/material_compiler.hpp"
#include "nodes/op_registry.hpp"

namespace wg {
namespace {

TEST(LibraryFunctions, SplitsFunctionsWithTheirCommentsAndCalls) {
  const std::string text =
      "// about a\n"
      "float wg_a(float x) { return x; }  // eq. 1\n"
      "const float kScale = 2.0;\n"
      "// b calls a; wg_c( in a comment is no call\n"
      "float wg_b(float x) {\n"
      "  return wg_a(x) * kScale;\n"
      "}\n"
      "// trailing\n";
  auto pieces = splitLibrary(text);
  ASSERT_EQ(pieces.size(), 4u);
  EXPECT_EQ(pieces[0].function, "wg_a");
  EXPECT_EQ(pieces[0].text, "// about a\nfloat wg_a(float x) { return x; }  // eq. 1\n");
  EXPECT_TRUE(pieces[1].function.empty());  // a global: always kept
  EXPECT_EQ(pieces[2].function, "wg_b");
  EXPECT_EQ(pieces[2].calls, std::vector<std::string_view>{"wg_a"});
  EXPECT_EQ(pieces[3].text, "// trailing\n");
  std::string joined;
  for (const auto& piece : pieces) joined += piece.text;
  EXPECT_EQ(joined, text);
}

// Every wg_ function a bundled graph's stage defines is called in that stage, and the
// weathered vertex stage no longer carries the fragment-only weather functions.
TEST(LibraryFunctions, StagesDefineOnlyTheFunctionsTheyCall) {
  const std::regex definition(R"((?:^|\n)\w+ (wg_\w+)\()");
  std::size_t stages = 0;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(WG_SOURCE_DIR) + "/graphs")) {
    if (entry.path().extension() != ".json") continue;
    auto result = compileMaterialFile(entry.path().string(), CompileOptions{.emitSpirv = false});
    ASSERT_TRUE(result.material) << entry.path();
    for (const auto& stage : result.material->stages) {
      ++stages;
      const std::string& text = stage.source;
      for (std::sregex_iterator it(text.begin(), text.end(), definition), end; it != end; ++it) {
        std::string name = (*it)[1];
        std::size_t calls = 0;
        forEachLibraryCall(text, [&](std::string_view called) { calls += called == name; });
        EXPECT_GE(calls, 2u) << entry.path().filename() << " " << name << " is defined but never called";
      }
    }
  }
  EXPECT_EQ(stages, 32u);
  auto rock = compileMaterialFile(std::string(WG_SOURCE_DIR) + "/graphs/rock.json", CompileOptions{.emitSpirv = false});
  ASSERT_TRUE(rock.material);
  const std::string& vertex = rock.material->stage(ShaderLanguage::Glsl, ShaderStage::Vertex).source;
  EXPECT_NE(vertex.find("wg_snow_offset("), std::string::npos);
  EXPECT_EQ(vertex.find("wg_moss_albedo("), std::string::npos);
  EXPECT_EQ(vertex.find("wg_wet_normal("), std::string::npos);
}

// glslang passes a const parameter by value; any other `in` parameter gets a copy in a
// function variable at every call, stored there and loaded back: a fifth of a weathered
// stage's unoptimised SPIR-V, and more of its validation time. So every library
// parameter its function never assigns is declared const.
std::vector<std::string> nonConstUnassignedParameters(std::string_view library) {
  std::vector<std::string> found;
  for (const LibraryPiece& piece : splitLibrary(library)) {
    if (piece.function.empty()) continue;
    std::string text(piece.text.substr(static_cast<std::size_t>(piece.function.data() - piece.text.data())));
    std::size_t open = text.find('('), close = text.find(')'), body = text.find('{');
    std::string parameters = text.substr(open + 1, close - open - 1);
    std::string bodyText = text.substr(body);
    std::stringstream list(parameters);
    for (std::string parameter; std::getline(list, parameter, ',');) {
      std::stringstream words(parameter);
      std::string first, word, name;
      words >> first;
      for (name = first; words >> word;) name = word;
      if (first.empty() || first == "const" || first == "out" || first == "inout") continue;
      const std::regex assigned("\\b" + name + "\\b(\\.\\w+)?\\s*([-+*/]?=[^=]|\\+\\+|--)");
      if (!std::regex_search(bodyText, assigned)) found.push_back(std::string(piece.function) + "(" + name + ")");
    }
  }
  return found;
}

TEST(LibraryFunctions, ParametersTheirFunctionNeverAssignsAreConst) {
  std::size_t libraries = 0;
  for (const ShaderLibrary* library : allShaderLibraries()) {
    ++libraries;
    EXPECT_EQ(nonConstUnassignedParameters(library->glsl), std::vector<std::string>{}) << library->name;
    EXPECT_EQ(nonConstUnassignedParameters(derivedHlsl(*library)), std::vector<std::string>{})
        << library->name << " (HLSL)";
  }
  EXPECT_GE(libraries, 8u);
  // The check itself finds an unmarked parameter and passes an assigned one.
  EXPECT_EQ(nonConstUnassignedParameters("float wg_a(float x, const float y) { return x + y; }\n"),
            std::vector<std::string>{"wg_a(x)"});
  EXPECT_EQ(nonConstUnassignedParameters("float wg_b(float x) {\n  x.y += 1.0;\n  return x;\n}\n"),
            std::vector<std::string>{});
}

}  // namespace
}  // namespace wg
