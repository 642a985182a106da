// The generated C++ uniform headers: each compiles on its own as C++17 with its
// static_asserts (so the compiler proves the std140 layout), and a second set of
// asserts, written here from the reflection JSON, proves it names every member of both
// blocks at the reflected offset, with the reflected sizes, sets and bindings.
// -Wpadded makes any padding the C++ compiler adds by itself an error: the header's
// explicit padding must account for every byte.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "compiler/cpp_header.hpp"
#include "driver/material_compiler.hpp"
#include "process_support.hpp"

namespace wg {
namespace {

using testing::bundledGraphs;
using testing::readFile;
using testing::runCommand;
using testing::shellQuote;
using testing::TempDir;
namespace fs = std::filesystem;

const std::string kCompileFlags = "-std=c++17 -fsyntax-only -Wall -Wextra -Wpadded -pedantic -Werror";

struct Emitted {
  std::string header;
  nlohmann::json reflection;
};

Emitted emit(const std::string& file, const std::string& text) {
  CompileOptions options;
  options.emitCppHeader = true;  // SPIR-V stays on: the compiler checks its offsets against the reflection
  CompileResult r = compileMaterialText(file, text, options);
  for (const auto& d : r.diagnostics.items()) ADD_FAILURE() << formatDiagnosticText(d);
  if (!r.material) return {};
  return {r.material->cppHeader, nlohmann::json::parse(r.material->reflectionJson)};
}

std::string assertLine(const std::string& condition) {
  std::string message;
  for (char c : condition) message += c == '"' ? std::string("\\\"") : std::string(1, c);
  return "static_assert(" + condition + ", \"reflection: " + message + "\");\n";
}

// A translation unit that includes the header and checks it against the reflection.
std::string reflectionChecks(const std::string& headerName, const nlohmann::json& reflection) {
  const std::string ns = "weathergen_materials::" + cppMaterialNamespace(reflection["material"].get<std::string>());
  std::string tu = "#include \"" + headerName + "\"\n#include <cstddef>\n\nnamespace m = " + ns + ";\n\n";
  tu += "constexpr bool same(const char* a, const char* b) { return *a == *b && (*a == 0 || same(a + 1, b + 1)); }\n";
  tu += assertLine("same(m::kContentHash, \"" + reflection["contentHash"].get<std::string>() + "\")");
  for (const auto& block : reflection["blocks"]) {
    const std::string id = block["identifier"].get<std::string>();
    const std::string prefix = id == "FrameBlock" ? "kFrame" : "kMaterial";
    tu += assertLine("m::" + prefix + "Set == " + std::to_string(block["set"].get<unsigned>()));
    tu += assertLine("m::" + prefix + "Binding == " + std::to_string(block["binding"].get<unsigned>()));
    if (block["members"].empty()) {
      tu += assertLine("!m::kHasMaterialBlock");
      continue;
    }
    tu += assertLine("sizeof(m::" + id + ") == " + std::to_string(block["size"].get<unsigned>()));
    for (const auto& member : block["members"]) {
      const std::string field = "m::" + id + "{}." + member["identifier"].get<std::string>();
      tu += assertLine("offsetof(m::" + id + ", " + member["identifier"].get<std::string>() +
                       ") == " + std::to_string(member["offset"].get<unsigned>()));
      tu += assertLine("sizeof(" + field + ") == " + std::to_string(member["size"].get<unsigned>()));
    }
  }
  for (const char* list : {"textures", "weatherMaps"})
    for (const auto& t : reflection[list]) {
      const std::string slot = "m::" + t["textureIdentifier"].get<std::string>();
      tu += assertLine(slot + ".set == " + std::to_string(t["set"].get<unsigned>()));
      tu += assertLine(slot + ".textureBinding == " + std::to_string(t["binding"].get<unsigned>()));
      tu += assertLine(slot + ".samplerBinding == " + std::to_string(t["samplerBinding"].get<unsigned>()));
    }
  return tu;
}

void expectHeaderMatchesReflection(const std::string& stem, const Emitted& emitted) {
  ASSERT_FALSE(emitted.header.empty());
  TempDir dir("cpp-header");
  testing::writeFile(dir.path() / (stem + ".hpp"), emitted.header);
  // The header alone, then the header under the reflection's asserts.
  testing::writeFile(dir.path() / "alone.cpp", "#include \"" + stem + ".hpp\"\n");
  testing::writeFile(dir.path() / "checks.cpp", reflectionChecks(stem + ".hpp", emitted.reflection));
  for (const char* tu : {"alone.cpp", "checks.cpp"}) {
    auto r = runCommand("c++ " + kCompileFlags + " -I " + shellQuote(dir.path().string()) + " " +
                        shellQuote((dir.path() / tu).string()));
    EXPECT_EQ(r.exitCode, 0) << tu << ":\n"
                             << r.output << "\n--- header ---\n"
                             << emitted.header << "\n--- " << tu << " ---\n"
                             << readFile(dir.path() / tu);
  }
}

std::string graphName(const ::testing::TestParamInfo<fs::path>& info) { return info.param.stem().string(); }

class BundledHeader : public ::testing::TestWithParam<fs::path> {};

TEST_P(BundledHeader, CompilesAndMatchesTheReflection) {
  Emitted emitted = emit(GetParam().string(), readFile(GetParam()));
  expectHeaderMatchesReflection(GetParam().stem().string(), emitted);
}

INSTANTIATE_TEST_SUITE_P(Graphs, BundledHeader, ::testing::ValuesIn(bundledGraphs()), graphName);

// The CLI's --emit-header writes the same header beside the reflection it must match.
TEST(CppHeader, CliEmitHeaderWritesAHeaderMatchingItsReflectionFile) {
  TempDir out("cli-header");
  const fs::path rock = fs::path(WG_SOURCE_DIR) / "graphs" / "rock.json";
  auto r = runCommand(shellQuote(WG_CLI_PATH) + " compile " + shellQuote(rock.string()) + " -o " +
                      shellQuote(out.path().string()) + " --target glsl --emit-header -q");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  Emitted fromCli{readFile(out.path() / "rock.hpp"), nlohmann::json::parse(readFile(out.path() / "rock.reflect.json"))};
  expectHeaderMatchesReflection("rock", fromCli);
  // Without the flag there is no header.
  TempDir plain("cli-no-header");
  ASSERT_EQ(runCommand(shellQuote(WG_CLI_PATH) + " compile " + shellQuote(rock.string()) + " -o " +
                       shellQuote(plain.path().string()) + " --target glsl -q").exitCode, 0);
  EXPECT_FALSE(fs::exists(plain.path() / "rock.hpp"));
}

// Engines include many material headers in one translation unit.
TEST(CppHeader, AllBundledHeadersCompileTogether) {
  TempDir dir("cpp-headers");
  std::string tu;
  for (const auto& graph : bundledGraphs()) {
    Emitted emitted = emit(graph.string(), readFile(graph));
    testing::writeFile(dir.path() / (graph.stem().string() + ".hpp"), emitted.header);
    tu += "#include \"" + graph.stem().string() + ".hpp\"\n";
  }
  testing::writeFile(dir.path() / "all.cpp", tu);
  auto r = runCommand("c++ " + kCompileFlags + " " + shellQuote((dir.path() / "all.cpp").string()));
  EXPECT_EQ(r.exitCode, 0) << r.output;
}

// Every std140 case (vec3 then float packs, float then vec3 pads, vec2, bool as uint,
// vec4), names that are C++ words, macros or hostile text, and no weather.
std::string hostileGraph(const std::string& materialName) {
  nlohmann::json g;
  g["name"] = materialName;
  g["weather"] = "none";
  g["parameters"] = {
      {"a", {{"type", "float"}, {"default", 0.5}}},
      {"b", {{"type", "vec3"}, {"default", {0.1, 0.2, 0.3}}}},
      {"c", {{"type", "float"}, {"default", 0.25}}},
      {"d", {{"type", "vec2"}, {"default", {1.0, 2.0}}}},
      {"e", {{"type", "bool"}, {"default", true}}},
      {"f", {{"type", "vec4"}, {"default", {1.0, 2.0, 3.0, 4.0}}}},
      {"class", {{"type", "float"}, {"default", 0.1}}},
      {"offsetof", {{"type", "vec3"}, {"default", {0.1, 0.2, 0.3}}}},
      {"a;b */ #define x", {{"type", "float"}, {"default", 0.1}}},
      {"INT32_MAX", {{"type", "vec2"}, {"default", {0.1, 0.2}}}},
  };
  g["nodes"] = {{{"id", "r"}, {"op", "parameter"}, {"param", "a"}}};
  g["output"] = {{"roughness", "r.out"}};
  return g.dump();
}

TEST(CppHeader, HostileNamesGiveValidCppAndNeverAppear) {
  const std::vector<std::string> names = {"and", "INT32_MAX", "weathergen_materials", "linux", "offsetof",
                                          "a;discard;// \xe9\x9b\xaa */ #define"};
  for (std::size_t i = 0; i < names.size(); ++i) {
    SCOPED_TRACE("material name #" + std::to_string(i));
    Emitted emitted = emit("hostile.json", hostileGraph(names[i]));
    ASSERT_EQ(emitted.reflection["blocks"][1]["members"].size(), 10u);
    EXPECT_EQ(emitted.header.find("#define"), std::string::npos);
    EXPECT_EQ(emitted.header.find("\xe9\x9b\xaa"), std::string::npos);
    EXPECT_EQ(emitted.header.find(";discard"), std::string::npos);  // sanitised to "a_discard" at most
    EXPECT_EQ(emitted.header.find("*/"), std::string::npos);
    expectHeaderMatchesReflection("hostile" + std::to_string(i), emitted);
  }
}

TEST(CppHeader, MaterialWithoutParametersHasNoMaterialBlock) {
  nlohmann::json g = {{"name", "plain"}, {"weather", "none"}, {"nodes", nlohmann::json::array()},
                      {"output", {{"roughness", 0.5}}}};
  Emitted emitted = emit("plain.json", g.dump());
  ASSERT_TRUE(emitted.reflection["blocks"][1]["members"].empty()) << emitted.reflection.dump(2);
  EXPECT_EQ(emitted.header.find("struct alignas(16) MaterialBlock"), std::string::npos);
  EXPECT_NE(emitted.header.find("kHasMaterialBlock = false"), std::string::npos);
  expectHeaderMatchesReflection("plain", emitted);
}

}  // namespace
}  // namespace wg
