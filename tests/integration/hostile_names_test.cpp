// User text never reaches emitted code raw: hostile parameter, texture and node names
// still give shaders that every validator accepts, and none of the text appears.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "driver/material_compiler.hpp"
#include "process_support.hpp"

namespace wg {
namespace {

const std::vector<std::string> kHostile = {
    "a;discard;//", "else", "gl_Position", "__x", "x__y", "caf\xc3\xa9 \xe9\x9b\xaa", std::string(10000, 'n'),
    "*/ #define main evil /*", "\n}\nvoid main(){", "SV_Target", "mat_a", "mat a"};

std::string hostileGraph() {
  nlohmann::json g;
  g["name"] = "a;discard;// \xe9\x9b\xaa";
  g["parameters"] = nlohmann::json::object();
  g["textures"] = nlohmann::json::object();
  g["nodes"] = nlohmann::json::array();
  std::string sum;
  int i = 0;
  for (const auto& name : kHostile) {
    g["parameters"][name] = {{"type", "float"}, {"default", 0.1 * (i + 1)}, {"label", name}};
    g["textures"][name] = {{"generator", "fbm"}, {"seed", i}, {"size", 16}};
    std::string param = name + ".p", tex = name + ".t";
    g["nodes"].push_back({{"id", param}, {"op", "parameter"}, {"param", name}});
    g["nodes"].push_back({{"id", tex}, {"op", "sample"}, {"inputs", {{"texture", name}, {"uv", {0.5, 0.5}}}}});
    std::string mul = name + ".m";
    g["nodes"].push_back({{"id", mul}, {"op", "multiply"}, {"inputs", {{"a", param + ".out"}, {"b", tex + ".r"}}}});
    std::string acc = "sum" + std::to_string(i);
    g["nodes"].push_back({{"id", acc}, {"op", "add"}, {"inputs", {{"a", sum.empty() ? nlohmann::json(0.0) : nlohmann::json(sum)}, {"b", mul + ".out"}}}});
    sum = acc + ".out";
    ++i;
  }
  g["output"] = {{"roughness", sum}};
  return g.dump();
}

TEST(HostileNames, CompileValidateAndNeverAppearInCode) {
  CompileResult r = compileMaterialText("hostile.json", hostileGraph(), {});
  for (const auto& d : r.diagnostics.items()) ADD_FAILURE() << formatDiagnosticText(d);
  ASSERT_TRUE(r.material);
  for (const auto& stage : r.material->stages) {
    EXPECT_FALSE(stage.spirv.empty());
    EXPECT_EQ(stage.source.find("discard;//"), std::string::npos);
    EXPECT_EQ(stage.source.find("#define"), std::string::npos);
    EXPECT_EQ(stage.source.find("\xe9\x9b\xaa"), std::string::npos);
    EXPECT_EQ(stage.source.find(" gl_Position;"), std::string::npos);
    EXPECT_EQ(stage.source.find(std::string(100, 'n')), std::string::npos);
    EXPECT_EQ(stage.source.find("__"), std::string::npos);
  }
  EXPECT_EQ(r.material->fileStem.find('/'), std::string::npos);
  EXPECT_EQ(r.material->fileStem.find(';'), std::string::npos);
  // Every parameter is still published under its real name.
  auto reflection = nlohmann::json::parse(r.material->reflectionJson);
  std::size_t members = reflection["blocks"][1]["members"].size();
  EXPECT_EQ(members, kHostile.size());
}

TEST(HostileNames, CliOutputsPassIndependentValidators) {
  testing::TempDir dir("hostile");
  testing::writeFile(dir.path() / "g.json", hostileGraph());
  auto r = testing::runCommand(testing::shellQuote(WG_CLI_PATH) + " compile " +
                               testing::shellQuote((dir.path() / "g.json").string()) + " -o " +
                               testing::shellQuote((dir.path() / "out").string()));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  for (const auto& name : testing::listFiles(dir.path() / "out")) {
    auto file = testing::shellQuote((dir.path() / "out" / name).string());
    std::string stage = name.find(".vert.") != std::string::npos ? "vert" : "frag";
    if (name.ends_with(".glsl")) {
      EXPECT_EQ(testing::runCommand(testing::shellQuote(WG_GLSLANG_VALIDATOR) + " -V -S " + stage + " " + file + " -o /dev/null").exitCode, 0) << name;
    }
    if (name.ends_with(".hlsl")) {
      EXPECT_EQ(testing::runCommand(testing::shellQuote(WG_GLSLANG_VALIDATOR) + " -V -D -e main -S " + stage + " " + file + " -o /dev/null").exitCode, 0) << name;
    }
  }
}

// A name with ESC sequences reaches the JSON pointer of a diagnostic; text
// diagnostics print the pointer with control characters escaped, like the message.
TEST(HostileNames, EscapeSequencesInPointersNeverReachTheTerminal) {
  testing::TempDir dir("hostile");
  testing::writeFile(dir.path() / "g.json", R"({"name": "g", "parameters": {"\u001b[2J\u001b[31mx": {"type": "vec5", "default": 1}},
    "nodes": [], "output": {}})");
  auto r = testing::runCommand(testing::shellQuote(WG_CLI_PATH) + " compile " + testing::shellQuote((dir.path() / "g.json").string()) +
                               " -o " + testing::shellQuote((dir.path() / "out").string()));
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_NE(r.output.find("WG2013"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find('\x1b'), std::string::npos) << "a raw ESC reached the terminal:\n" << r.output;
  EXPECT_NE(r.output.find("[/parameters/\\x1b[2J\\x1b[31mx"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace wg
