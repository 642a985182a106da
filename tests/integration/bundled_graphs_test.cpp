// Every bundled graph: compiles in both languages, passes the independent validators
// (glslangValidator, spirv-val), matches its golden SPIR-V, and compiles
// byte-identically however the file is ordered, spelled or invoked.
#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <random>

#include "process_support.hpp"

namespace wg {
namespace {

using testing::bundledGraphs;
using testing::listFiles;
using testing::readFile;
using testing::runCommand;
using testing::shellQuote;
using testing::TempDir;
namespace fs = std::filesystem;

const std::string kCli = WG_CLI_PATH;
// The byte-identity checks cover the surfaces too.
const std::string kEveryTarget = "--target all,surface";

std::string graphName(const ::testing::TestParamInfo<fs::path>& info) { return info.param.stem().string(); }

testing::CommandResult compile(const fs::path& graph, const fs::path& out, const std::string& extra = "") {
  return runCommand(shellQuote(kCli) + " compile " + shellQuote(graph.string()) + " -o " + shellQuote(out.string()) +
                    " " + extra);
}

class BundledGraph : public ::testing::TestWithParam<fs::path> {};

TEST_P(BundledGraph, CompilesAndPassesIndependentValidators) {
  TempDir dir("bundled");
  auto r = compile(GetParam(), dir.path());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  auto files = listFiles(dir.path());
  std::string stem = GetParam().stem().string();
  for (const char* suffix : {".vert.glsl", ".frag.glsl", ".vert.hlsl", ".frag.hlsl", ".glsl.vert.spv", ".glsl.frag.spv",
                             ".hlsl.vert.spv", ".hlsl.frag.spv", ".glsl.vert.spvasm", ".glsl.frag.spvasm",
                             ".hlsl.vert.spvasm", ".hlsl.frag.spvasm", ".reflect.json"})
    EXPECT_NE(std::find(files.begin(), files.end(), stem + suffix), files.end()) << stem + suffix;
  for (const auto& name : files) {
    fs::path file = dir.path() / name;
    std::string stage = name.find(".vert.") != std::string::npos ? "vert" : "frag";
    std::string command;
    if (name.ends_with(".glsl"))
      command = shellQuote(WG_GLSLANG_VALIDATOR) + " -V --target-env vulkan1.1 -S " + stage + " " +
                shellQuote(file.string()) + " -o /dev/null";
    else if (name.ends_with(".hlsl"))
      command = shellQuote(WG_GLSLANG_VALIDATOR) + " -V -D -e main --target-env vulkan1.1 -S " + stage + " " +
                shellQuote(file.string()) + " -o /dev/null";
    else if (name.ends_with(".spv"))
      command = shellQuote(WG_SPIRV_VAL) + " --target-env vulkan1.1 " + shellQuote(file.string());
    else
      continue;
    auto v = runCommand(command);
    EXPECT_EQ(v.exitCode, 0) << name << ":\n" << v.output;
  }
  auto reflection = nlohmann::json::parse(readFile(dir.path() / (stem + ".reflect.json")));
  EXPECT_EQ(reflection["material"], stem);
  EXPECT_EQ(reflection["contentHash"].get<std::string>().size(), 16u);
}

// --target msl,glsles writes only the two translations per stage (and the reflection);
// the ES sources compile as ES with the independent validator.
TEST_P(BundledGraph, MslAndGlslEsTargetsWriteTranslations) {
  TempDir dir("cross");
  auto r = compile(GetParam(), dir.path(), "--target msl,glsles");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  std::string stem = GetParam().stem().string();
  std::vector<std::string> expected = {stem + ".frag.es.glsl", stem + ".frag.msl", stem + ".reflect.json",
                                       stem + ".vert.es.glsl", stem + ".vert.msl"};
  auto files = listFiles(dir.path());
  std::sort(files.begin(), files.end());
  EXPECT_EQ(files, expected);
  for (const char* stage : {"vert", "frag"}) {
    fs::path es = dir.path() / (stem + "." + stage + ".es.glsl");
    EXPECT_TRUE(readFile(es).starts_with("#version 310 es"));
    auto v = runCommand(shellQuote(WG_GLSLANG_VALIDATOR) + " -S " + stage + " " + shellQuote(es.string()));
    EXPECT_EQ(v.exitCode, 0) << es << ":\n" << v.output;
    std::string msl = readFile(dir.path() / (stem + "." + stage + ".msl"));
    EXPECT_NE(msl.find("#include <metal_stdlib>"), std::string::npos);
    EXPECT_NE(msl.find(std::string(stage) == "vert" ? "vertex " : "fragment "), std::string::npos);
    EXPECT_NE(msl.find(" main0("), std::string::npos);
  }
}

TEST_P(BundledGraph, OptimizedSpirvIsValid) {
  TempDir dir("optimized");
  auto r = compile(GetParam(), dir.path(), "--target spirv -O");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  for (const auto& name : listFiles(dir.path()))
    if (name.ends_with(".spv")) {
      auto v = runCommand(shellQuote(WG_SPIRV_VAL) + " --target-env vulkan1.1 " + shellQuote((dir.path() / name).string()));
      EXPECT_EQ(v.exitCode, 0) << name << ":\n" << v.output;
    }
}

// Golden SPIR-V: any change fails and prints the diff. Regenerate with
// scripts/update-golden.sh and review the diff before committing.
TEST_P(BundledGraph, MatchesGoldenSpirv) {
  TempDir dir("golden");
  auto r = compile(GetParam(), dir.path(), "--target spirv -O0");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  fs::path golden = fs::path(WG_SOURCE_DIR) / "tests" / "golden";
  int compared = 0;
  for (const auto& name : listFiles(dir.path())) {
    if (!name.ends_with(".spvasm")) continue;
    ++compared;
    fs::path expected = golden / name;
    ASSERT_TRUE(fs::exists(expected)) << "no golden file " << expected << "; run scripts/update-golden.sh";
    if (readFile(expected) != readFile(dir.path() / name)) {
      auto diff = runCommand("diff -u " + shellQuote(expected.string()) + " " + shellQuote((dir.path() / name).string()));
      ADD_FAILURE() << name << " differs from its golden file (scripts/update-golden.sh regenerates it):\n"
                    << diff.output.substr(0, 8000);
    }
  }
  EXPECT_EQ(compared, 4);
}

// Golden surfaces (--target surface): the host contract's text changes only on purpose.
TEST_P(BundledGraph, MatchesGoldenSurfaces) {
  TempDir dir("golden-surface");
  auto r = compile(GetParam(), dir.path(), "--target surface");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  fs::path golden = fs::path(WG_SOURCE_DIR) / "tests" / "golden";
  int compared = 0;
  for (const auto& name : listFiles(dir.path())) {
    if (name.find(".surface.") == std::string::npos) continue;
    ++compared;
    fs::path expected = golden / name;
    ASSERT_TRUE(fs::exists(expected)) << "no golden file " << expected << "; run scripts/update-golden.sh";
    if (readFile(expected) != readFile(dir.path() / name)) {
      auto diff = runCommand("diff -u " + shellQuote(expected.string()) + " " + shellQuote((dir.path() / name).string()));
      ADD_FAILURE() << name << " differs from its golden file (scripts/update-golden.sh regenerates it):\n"
                    << diff.output.substr(0, 8000);
    }
  }
  EXPECT_EQ(compared, 3);
}

// Renames every node id and shuffles the node array; links follow the renames.
std::string shuffledAndRenamed(const std::string& text, unsigned seed) {
  auto graph = nlohmann::ordered_json::parse(text);
  std::map<std::string, std::string> renamed;
  int k = 0;
  for (auto& node : graph["nodes"]) {
    std::string id = node["id"];
    renamed[id] = "r" + std::to_string(seed) + "_" + std::to_string(k++) + "_" + std::string(id.rbegin(), id.rend());
    node["id"] = renamed[id];
  }
  auto relink = [&](nlohmann::ordered_json& value) {
    if (!value.is_string()) return;
    std::string s = value;
    auto dot = s.rfind('.');
    if (dot == std::string::npos) return;
    auto it = renamed.find(s.substr(0, dot));
    if (it != renamed.end()) value = it->second + s.substr(dot);
  };
  for (auto& node : graph["nodes"])
    for (const char* sources : {"inputs", "cases"})  // a switch node's cases are links too
      if (node.contains(sources))
        for (auto& [port, value] : node[sources].items()) relink(value);
  for (auto& [field, value] : graph["output"].items()) relink(value);
  std::mt19937 rng(seed);
  auto& nodes = graph["nodes"];
  std::vector<nlohmann::ordered_json> list(nodes.begin(), nodes.end());
  std::shuffle(list.begin(), list.end(), rng);
  nodes = list;
  return graph.dump(1);
}

void expectSameOutputs(const fs::path& a, const fs::path& b) {
  auto filesA = listFiles(a), filesB = listFiles(b);
  ASSERT_EQ(filesA, filesB);
  ASSERT_FALSE(filesA.empty());
  for (const auto& name : filesA) EXPECT_TRUE(readFile(a / name) == readFile(b / name)) << name << " differs";
}

TEST_P(BundledGraph, ByteIdenticalWhenCompiledTwice) {
  TempDir first("twice-a"), second("twice-b");
  ASSERT_EQ(compile(GetParam(), first.path(), kEveryTarget).exitCode, 0);
  ASSERT_EQ(compile(GetParam(), second.path(), kEveryTarget).exitCode, 0);
  expectSameOutputs(first.path(), second.path());
}

TEST_P(BundledGraph, ByteIdenticalFromAnotherWorkingDirectory) {
  TempDir first("cwd-a"), second("cwd-b");
  ASSERT_EQ(compile(GetParam(), first.path(), kEveryTarget).exitCode, 0);
  auto rel = fs::relative(GetParam(), fs::path(WG_SOURCE_DIR));
  auto r = runCommand("cd " + shellQuote(WG_SOURCE_DIR) + " && " + shellQuote(kCli) + " compile " +
                      shellQuote(rel.string()) + " -o " + shellQuote(second.path().string()) + " " + kEveryTarget);
  ASSERT_EQ(r.exitCode, 0) << r.output;
  expectSameOutputs(first.path(), second.path());
}

TEST_P(BundledGraph, ByteIdenticalWithShuffledNodesAndRenamedIds) {
  TempDir original("orig"), variant("variant");
  ASSERT_EQ(compile(GetParam(), original.path() / "out", kEveryTarget).exitCode, 0);
  for (unsigned seed : {1u, 2u, 3u}) {
    fs::path graph = variant.path() / ("graph" + std::to_string(seed) + ".json");
    testing::writeFile(graph, shuffledAndRenamed(readFile(GetParam()), seed));
    fs::path out = variant.path() / ("out" + std::to_string(seed));
    auto r = compile(graph, out, kEveryTarget);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    expectSameOutputs(original.path() / "out", out);
  }
}

INSTANTIATE_TEST_SUITE_P(Graphs, BundledGraph, ::testing::ValuesIn(bundledGraphs()), graphName);

}  // namespace
}  // namespace wg
