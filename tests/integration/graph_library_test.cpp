// Graph libraries ("include"): a library's parameters, textures and nodes join the graph
// under its alias, its errors name its own file, and depfiles list it.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "driver/material_compiler.hpp"
#include "process_support.hpp"

namespace wg {
namespace {

using testing::readFile;
using testing::runCommand;
using testing::shellQuote;
using testing::TempDir;
using testing::writeFile;
namespace fs = std::filesystem;

// A library with a parameter, a procedural and a file texture, a swizzle (whose
// "channels" must not be renamed) and links between its own nodes.
constexpr const char* kStoneLibrary = R"({
  "description": "stone albedo",
  "parameters": {"tint": {"type": "vec3", "default": [0.6, 0.55, 0.5], "min": 0, "max": 1}},
  "textures": {
    "noise": {"generator": "fbm", "seed": 3, "size": 64, "scale": 4, "octaves": 3},
    "mud": {"file": "tex/mud.png"}
  },
  "nodes": [
    {"id": "uv", "op": "texcoord"},
    {"id": "sample", "op": "sample", "inputs": {"texture": "noise", "uv": "uv.out"}},
    {"id": "mudSample", "op": "sample", "inputs": {"texture": "mud", "uv": "uv.out"}},
    {"id": "tint", "op": "parameter", "param": "tint"},
    {"id": "albedo", "op": "multiply", "inputs": {"a": "sample.rgb", "b": "tint.out"}},
    {"id": "mixed", "op": "lerp", "inputs": {"a": "albedo.out", "b": "mudSample.rgb", "t": 0.3}},
    {"id": "red", "op": "swizzle", "inputs": {"in": "mixed.out", "channels": "x"}}
  ]
})";

std::string wallGraph(const std::string& library) {
  return R"({"name": "wall", "include": {"stone": ")" + library + R"("},
    "nodes": [{"id": "rough", "op": "one_minus", "inputs": {"in": "stone.red.out"}}],
    "output": {"baseColor": "stone.mixed.out", "roughness": "rough.out"}})";
}

class GraphLibrary : public ::testing::Test {
 protected:
  void SetUp() override {
    fs::create_directories(dir_.path() / "lib" / "tex");
    writeFile(dir_.path() / "lib" / "stone.json", kStoneLibrary);
    fs::copy_file(fs::path(WG_SOURCE_DIR) / "examples/cmake-consumer/materials/textures/mud_albedo.png",
                  dir_.path() / "lib" / "tex" / "mud.png");
    writeFile(dir_.path() / "wall.json", wallGraph("lib/stone.json"));
  }
  fs::path graph() const { return dir_.path() / "wall.json"; }
  TempDir dir_{"graph-library"};
};

TEST_F(GraphLibrary, ItsElementsJoinTheGraphUnderTheAlias) {
  CompileOptions options;
  options.emitSpirv = false;
  CompileResult r = compileMaterialFile(graph().string(), options);
  ASSERT_TRUE(r.material) << (r.diagnostics.empty() ? "" : formatDiagnosticText(r.diagnostics.items().front()));
  auto reflection = nlohmann::json::parse(r.material->reflectionJson);
  std::vector<std::string> textures;
  for (const auto& t : reflection["textures"]) textures.push_back(t["name"]);
  EXPECT_EQ(textures, (std::vector<std::string>{"stone.mud", "stone.noise"}));
  // The library's file texture is reported relative to the including graph.
  EXPECT_EQ(reflection["textures"][0]["source"]["file"], "lib/tex/mud.png");
  bool tintFound = false;
  for (const auto& block : reflection["blocks"])
    for (const auto& m : block["members"]) tintFound = tintFound || m["name"] == "stone.tint";
  EXPECT_TRUE(tintFound) << reflection["blocks"].dump();
  EXPECT_EQ(r.material->ir.includedFiles, (std::vector<std::string>{(dir_.path() / "lib" / "stone.json").string()}));
}

TEST_F(GraphLibrary, IncludingIsTheSameAsWritingItInline) {
  // The same nodes written in the graph under the prefixed names give the same shaders.
  nlohmann::json library = nlohmann::json::parse(kStoneLibrary);
  nlohmann::json inlined = nlohmann::json::parse(wallGraph("unused"));
  inlined.erase("include");
  for (auto& [name, p] : library["parameters"].items()) inlined["parameters"]["stone." + name] = p;
  for (auto& [name, t] : library["textures"].items()) {
    if (t.contains("file")) t["file"] = "lib/" + t["file"].get<std::string>();
    inlined["textures"]["stone." + name] = t;
  }
  for (auto node : library["nodes"]) {
    node["id"] = "stone." + node["id"].get<std::string>();
    if (node.contains("param")) node["param"] = "stone." + node["param"].get<std::string>();
    if (node.contains("inputs"))
      for (auto& [port, value] : node["inputs"].items())
        if (value.is_string() && port != "channels") value = "stone." + value.get<std::string>();
    inlined["nodes"].push_back(node);
  }
  writeFile(dir_.path() / "inline.json", inlined.dump(1));
  CompileOptions options;
  options.emitSpirv = false;
  CompileResult a = compileMaterialFile(graph().string(), options);
  CompileResult b = compileMaterialFile((dir_.path() / "inline.json").string(), options);
  ASSERT_TRUE(a.material && b.material)
      << (b.diagnostics.empty() ? "" : formatDiagnosticText(b.diagnostics.items().front()));
  EXPECT_EQ(a.material->contentHash, b.material->contentHash);
  EXPECT_EQ(a.material->stages[1].source, b.material->stages[1].source);
}

TEST_F(GraphLibrary, DepfileListsTheLibraryAndItsImages) {
  fs::path depfile = dir_.path() / "out.d";
  auto r = runCommand(shellQuote(WG_CLI_PATH) + " compile " + shellQuote(graph().string()) + " --target glsl -o " +
                      shellQuote((dir_.path() / "out").string()) + " --depfile " + shellQuote(depfile.string()));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  std::string d = readFile(depfile);
  EXPECT_NE(d.find("lib/stone.json"), std::string::npos) << d;
  EXPECT_NE(d.find("lib/tex/mud.png"), std::string::npos) << d;
}

// Compiles `graph` with JSON diagnostics: the exit code and the first diagnostic.
std::pair<int, nlohmann::json> firstDiagnostic(const fs::path& graph, const fs::path& out) {
  auto r = runCommand(shellQuote(WG_CLI_PATH) + " compile " + shellQuote(graph.string()) + " --diagnostics json -o " +
                      shellQuote(out.string()) + " 2>&1");
  auto start = r.output.find('[');
  if (start == std::string::npos) return {r.exitCode, r.output};
  auto parsed = nlohmann::json::parse(r.output.substr(start), nullptr, false);
  if (!parsed.is_array() || parsed.empty()) return {r.exitCode, r.output};
  return {r.exitCode, parsed[0]};
}

TEST_F(GraphLibrary, ErrorsInsideALibraryNameItsFileLineAndColumn) {
  std::string broken = kStoneLibrary;
  broken.replace(broken.find("\"texcoord\""), 10, "\"texcord\"");
  writeFile(dir_.path() / "lib" / "stone.json", broken);
  auto [exit, d] = firstDiagnostic(graph(), dir_.path() / "out");
  EXPECT_EQ(exit, 1);
  ASSERT_TRUE(d.is_object()) << d.dump();
  EXPECT_EQ(d["code"], "WG2001");
  EXPECT_NE(d["file"].get<std::string>().find("lib/stone.json"), std::string::npos) << d.dump();
  EXPECT_EQ(d["pointer"], "/nodes/0/op");
  EXPECT_EQ(d["line"], 9);
  EXPECT_FALSE(fs::exists(dir_.path() / "out"));
}

TEST_F(GraphLibrary, BadIncludesAreReportedByCode) {
  auto codeOf = [&](const std::string& text) {
    writeFile(dir_.path() / "bad.json", text);
    auto [exit, d] = firstDiagnostic(dir_.path() / "bad.json", dir_.path() / "bad-out");
    EXPECT_EQ(exit, 1) << text;
    EXPECT_FALSE(fs::exists(dir_.path() / "bad-out"));
    return d.is_object() ? d["code"].get<std::string>() : d.dump();
  };
  EXPECT_EQ(codeOf(wallGraph("lib/missing.json")), "WG1002");
  EXPECT_EQ(codeOf(wallGraph("lib")), "WG1002");  // a directory
  writeFile(dir_.path() / "lib" / "empty.json", "");
  EXPECT_EQ(codeOf(wallGraph("lib/empty.json")), "WG1002");  // never read: /proc files also claim size 0
  writeFile(dir_.path() / "lib" / "nested.json", R"({"include": {"x": "stone.json"}, "nodes": []})");
  EXPECT_EQ(codeOf(wallGraph("lib/nested.json")), "WG1005");
  writeFile(dir_.path() / "lib" / "truncated.json", R"({"nodes": [)");
  EXPECT_EQ(codeOf(wallGraph("lib/truncated.json")), "WG1001");
  EXPECT_EQ(codeOf(R"({"name": "w", "include": {"two words": "lib/stone.json"}, "nodes": [], "output": {}})"), "WG2021");
  // A graph parameter that a library also declares under the same prefixed name.
  EXPECT_EQ(codeOf(R"({"name": "w", "include": {"stone": "lib/stone.json"},
                       "parameters": {"stone.tint": {"type": "vec3", "default": [1, 1, 1]}}, "nodes": [], "output": {}})"),
            "WG2026");
}

}  // namespace
}  // namespace wg
