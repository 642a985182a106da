// `weathergen compile --variants`: every permutation under a stable name, identical
// shaders stored once by content hash, and the index mapping variants to files.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <set>

#include "process_support.hpp"

namespace wg {
namespace {

using testing::listFiles;
using testing::readFile;
using testing::runCommand;
using testing::shellQuote;
using testing::TempDir;
namespace fs = std::filesystem;

const std::string kRock = std::string(WG_SOURCE_DIR) + "/graphs/rock.json";

testing::CommandResult compileRock(const fs::path& out, const std::string& flags) {
  return runCommand(shellQuote(WG_CLI_PATH) + " compile " + shellQuote(kRock) + " -o " + shellQuote(out.string()) + " " + flags);
}

nlohmann::json readIndex(const fs::path& dir) { return nlohmann::json::parse(readFile(dir / "rock.variants.json")); }

nlohmann::json bundledRoad() { return nlohmann::json::parse(readFile(std::string(WG_SOURCE_DIR) + "/graphs/road.json")); }

// Writes `graph` as DIR/road.json and compiles its variants to DIR/out (GLSL).
testing::CommandResult compileVariantsOf(const nlohmann::json& graph, const fs::path& dir, const std::string& selection) {
  const fs::path file = dir / "road.json";
  testing::writeFile(file, graph.dump());
  return runCommand(shellQuote(WG_CLI_PATH) + " compile " + shellQuote(file.string()) + " -o " +
                    shellQuote((dir / "out").string()) + " --variants " + selection + " --target glsl");
}

std::vector<std::string> variantNames(const nlohmann::json& index) {
  std::vector<std::string> names;
  for (const auto& v : index["variants"]) names.push_back(v["name"]);
  return names;
}

TEST(Variants, AllEmitsEveryPermutationUnderAStableName) {
  TempDir dir("variants-all");
  auto r = compileRock(dir.path(), "--variants all --target glsl,spirv");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  nlohmann::json index = readIndex(dir.path());
  EXPECT_EQ(variantNames(index),
            (std::vector<std::string>{"moss=off,quality=low", "moss=off,quality=medium", "moss=off,quality=high",
                                      "moss=on,quality=low", "moss=on,quality=medium", "moss=on,quality=high"}));
  // With the rock preset every switch and tier changes the shaders: six file sets.
  EXPECT_EQ(index["shaderSetCount"], 6);
  for (const auto& v : index["variants"]) {
    std::string hash = v["contentHash"];
    auto reflection = nlohmann::json::parse(readFile(dir.path() / v["reflection"].get<std::string>()));
    EXPECT_EQ(reflection["contentHash"], hash);
    // The reflection names the variant's own shader files, and they exist.
    for (const auto& [stage, files] : reflection["files"].items()) {
      if (stage.rfind("glsl", 0) != 0) continue;
      EXPECT_TRUE(fs::exists(dir.path() / files["source"].get<std::string>())) << files["source"];
      EXPECT_TRUE(fs::exists(dir.path() / files["spirv"].get<std::string>())) << files["spirv"];
    }
  }
  // The default variant is exactly what a compile without --variants produces.
  TempDir plain("variants-plain");
  ASSERT_EQ(compileRock(plain.path(), "--target glsl,spirv").exitCode, 0);
  std::string defaultHash = index["variants"][5]["contentHash"];
  EXPECT_EQ(readFile(plain.path() / "rock.frag.glsl"), readFile(dir.path() / ("rock." + defaultHash + ".frag.glsl")));
}

TEST(Variants, IdenticalShadersAreStoredOnce) {
  // Without weather the moss switch changes nothing, so its two values share files;
  // rock's quality switch drops its detail normal map at the low tier only.
  TempDir dir("variants-dedupe");
  auto r = compileRock(dir.path(), "--variants all --weather-preset none --target glsl");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  nlohmann::json index = readIndex(dir.path());
  ASSERT_EQ(index["variantCount"], 6);
  EXPECT_EQ(index["shaderSetCount"], 2);
  std::set<std::string> hashes;
  for (const auto& v : index["variants"]) hashes.insert(v["contentHash"]);
  EXPECT_EQ(hashes.size(), 2u);
  EXPECT_EQ(index["variants"][0]["contentHash"], index["variants"][3]["contentHash"]);  // moss off/on, quality low
  EXPECT_EQ(index["variants"][1]["contentHash"], index["variants"][2]["contentHash"]);  // medium, high
  // Two file sets of 3 files (vert, frag, reflection) and the index.
  EXPECT_EQ(listFiles(dir.path()).size(), 2u * 3u + 1u);
}

TEST(Variants, ListSelectsSwitchesAndValues) {
  TempDir dir("variants-list");
  ASSERT_EQ(compileRock(dir.path() / "a", "--variants quality --target glsl").exitCode, 0);
  EXPECT_EQ(variantNames(readIndex(dir.path() / "a")),
            (std::vector<std::string>{"moss=on,quality=low", "moss=on,quality=medium", "moss=on,quality=high"}));
  ASSERT_EQ(compileRock(dir.path() / "b", "--variants " + shellQuote("moss=off,quality=high|low") + " --target glsl").exitCode, 0);
  EXPECT_EQ(variantNames(readIndex(dir.path() / "b")),
            (std::vector<std::string>{"moss=off,quality=low", "moss=off,quality=high"}));
}

// The tier is a variant axis of every graph. A road without ripple or specular
// anti-aliasing: medium and high differ only in relief, which a road (no snow or ice)
// cannot show, so they share one content hash; low drops sky exposure and differs.
TEST(Variants, TiersWithIdenticalShadersShareOneHash) {
  TempDir dir("variants-tiers");
  nlohmann::json road = bundledRoad();
  road["weather"] = {{"preset", "road"}, {"effects", {{"ripple", false}, {"specularAntiAliasing", false}}}};
  auto r = compileVariantsOf(road, dir.path(), "all");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  nlohmann::json index = nlohmann::json::parse(readFile(dir.path() / "out" / "road.variants.json"));
  EXPECT_EQ(index["switches"]["quality"]["values"], (std::vector<std::string>{"low", "medium", "high"}));
  EXPECT_EQ(index["switches"]["quality"]["default"], "high");
  EXPECT_EQ(variantNames(index), (std::vector<std::string>{"quality=low", "quality=medium", "quality=high"}));
  EXPECT_EQ(index["shaderSetCount"], 2);
  EXPECT_EQ(index["variants"][1]["contentHash"], index["variants"][2]["contentHash"]);
  EXPECT_NE(index["variants"][0]["contentHash"], index["variants"][1]["contentHash"]);
  // Each tier's reflection says what its shaders do.
  auto effects = [&](int v) {
    return nlohmann::json::parse(readFile(dir.path() / "out" / index["variants"][v]["reflection"].get<std::string>()))
        ["weather"]["effects"];
  };
  EXPECT_FALSE(effects(0)["skyExposure"].get<bool>());
  EXPECT_TRUE(effects(2)["skyExposure"].get<bool>());
  EXPECT_FALSE(effects(2)["relief"].get<bool>());
}

// --quality picks the tier a selection that does not name "quality" compiles at.
TEST(Variants, QualityIsTheDefaultOfTheTierAxis) {
  TempDir dir("variants-quality");
  ASSERT_EQ(compileRock(dir.path(), "--variants moss --quality medium --target glsl").exitCode, 0);
  nlohmann::json index = readIndex(dir.path());
  EXPECT_EQ(variantNames(index), (std::vector<std::string>{"moss=off,quality=medium", "moss=on,quality=medium"}));
  EXPECT_EQ(index["switches"]["quality"]["values"], (std::vector<std::string>{"low", "medium", "high"}));  // rock's own
  EXPECT_EQ(index["switches"]["quality"]["default"], "medium");
}

TEST(Variants, OutputIsByteIdenticalWhateverTheJobCount) {
  TempDir dir("variants-jobs");
  for (const char* jobs : {"1", "2"})
    ASSERT_EQ(compileRock(dir.path() / jobs, std::string("--variants all --target glsl,hlsl,spirv -j") + jobs).exitCode, 0);
  auto names = listFiles(dir.path() / "1");
  ASSERT_EQ(listFiles(dir.path() / "2"), names);
  for (const auto& name : names)
    EXPECT_TRUE(readFile(dir.path() / "1" / name) == readFile(dir.path() / "2" / name)) << name;
}

TEST(Variants, DepfileListsEveryVariantFile) {
  TempDir dir("variants-depfile");
  auto r = compileRock(dir.path() / "out", "--variants all --target glsl --depfile " + shellQuote((dir.path() / "d").string()));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  std::string depfile = readFile(dir.path() / "d");
  for (const auto& name : listFiles(dir.path() / "out")) EXPECT_NE(depfile.find(name), std::string::npos) << name;
}

TEST(Variants, BadSelectionsAreUsageErrorsAndWriteNothing) {
  TempDir dir("variants-bad");
  for (const char* selection : {"nosuch", "quality=ultra", "quality=", "moss=on|"}) {
    auto r = compileRock(dir.path() / "out", std::string("--variants ") + shellQuote(selection) + " --diagnostics json");
    EXPECT_EQ(r.exitCode, 2) << selection << ": " << r.output;
    EXPECT_NE(r.output.find("WG9001"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(dir.path() / "out")) << selection;
  }
}

// Every variant of a graph reports its error; the batch prints each one once, and the
// same error in another graph is that graph's own.
TEST(Variants, AnErrorEveryVariantMeetsIsPrintedOncePerGraph) {
  TempDir dir("variants-error");
  nlohmann::json graph = nlohmann::json::parse(readFile(kRock));
  graph["alphaCutoff"] = 2;
  const fs::path a = dir.path() / "a.json", b = dir.path() / "b.json";
  testing::writeFile(a, graph.dump());
  testing::writeFile(b, graph.dump());
  auto r = runCommand(shellQuote(WG_CLI_PATH) + " compile " + shellQuote(a.string()) + " " + shellQuote(b.string()) +
                      " --variants all --target glsl -o " + shellQuote((dir.path() / "out").string()));
  EXPECT_EQ(r.exitCode, 1) << r.output;
  std::size_t count = 0;
  for (std::size_t at = r.output.find("WG2010"); at != std::string::npos; at = r.output.find("WG2010", at + 1)) ++count;
  EXPECT_EQ(count, 2u) << r.output;
  EXPECT_NE(r.output.find("a.json"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("b.json"), std::string::npos) << r.output;
}

// A graph's own "quality" may have values that are no tier: a variant with one keeps
// the compile's tier instead of failing as an unknown tier.
TEST(Variants, OwnQualityValuesThatNameNoTierAreVariants) {
  TempDir dir("variants-own-quality");
  nlohmann::json road = bundledRoad();
  road["switches"] = {{"quality", {{"values", {"draft", "final"}}, {"default", "final"}}}};
  auto r = compileVariantsOf(road, dir.path(), "quality");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  nlohmann::json index = nlohmann::json::parse(readFile(dir.path() / "out" / "road.variants.json"));
  EXPECT_EQ(variantNames(index), (std::vector<std::string>{"quality=draft", "quality=final"}));
  EXPECT_EQ(index["variants"][0]["contentHash"], index["variants"][1]["contentHash"]);
}

}  // namespace
}  // namespace wg
