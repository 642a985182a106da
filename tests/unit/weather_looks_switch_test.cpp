// The weather's looks beyond seed 000's equations (relief, ripple, specular
// anti-aliasing) are effects a graph can switch off, like any other: each one off
// leaves its shader code out of both languages and says so in the reflection.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "driver/material_compiler.hpp"

namespace wg {
namespace {

using json = nlohmann::json;

std::string readFile(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// A bundled graph with its weather block replaced.
CompiledMaterial compiled(const std::string& graph, const json& weather) {
  json doc = json::parse(readFile(std::string(WG_SOURCE_DIR) + "/graphs/" + graph + ".json"));
  doc["weather"] = weather;
  CompileResult r = compileMaterialText(graph + ".json", doc.dump(), {});
  EXPECT_TRUE(r.material) << r.diagnostics.items().size();
  return r.material ? std::move(*r.material) : CompiledMaterial{};
}

std::string fragment(const CompiledMaterial& m, ShaderLanguage language = ShaderLanguage::Glsl) {
  return m.stage(language, ShaderStage::Fragment).source;
}
bool contains(const std::string& text, std::string_view piece) { return text.find(piece) != std::string::npos; }

json rockWith(const json& effects) { return {{"preset", "rock"}, {"effects", effects}}; }

TEST(WeatherLooksSwitch, ReliefOffLeavesSnowsLayerNormalFlat) {
  CompiledMaterial on = compiled("rock", "rock");
  CompiledMaterial off = compiled("rock", rockWith({{"relief", false}}));
  EXPECT_TRUE(contains(fragment(on), "= wg_noise_relief("));
  EXPECT_FALSE(contains(fragment(off), "= wg_noise_relief("));
  EXPECT_FALSE(contains(fragment(off, ShaderLanguage::Hlsl), "= wg_noise_relief("));
  // The snow itself stays.
  EXPECT_TRUE(contains(fragment(off), "= wg_snow_coverage("));
}

TEST(WeatherLooksSwitch, ReliefOffAlsoFlattensIcesOwnUndulation) {
  EXPECT_TRUE(contains(fragment(compiled("river", "river")), "= wg_noise_relief("));
  CompiledMaterial off = compiled("river", {{"preset", "river"}, {"effects", {{"relief", false}}}});
  EXPECT_FALSE(contains(fragment(off), "= wg_noise_relief("));
  EXPECT_TRUE(contains(fragment(off), "= wg_frost_coverage("));
}

TEST(WeatherLooksSwitch, RippleOffKeepsTheWetNormalAsItWas) {
  CompiledMaterial off = compiled("rock", rockWith({{"ripple", false}}));
  EXPECT_TRUE(contains(fragment(compiled("rock", "rock")), "= wg_wet_normal("));
  EXPECT_FALSE(contains(fragment(off), "= wg_wet_normal("));
  EXPECT_FALSE(contains(fragment(off, ShaderLanguage::Hlsl), "= wg_wet_normal("));
  EXPECT_TRUE(contains(fragment(off), "= wg_wet_roughness("));
}

TEST(WeatherLooksSwitch, SpecularAntiAliasingOffTakesNoDerivativeOfTheNormal) {
  CompiledMaterial on = compiled("road", "road");
  CompiledMaterial off = compiled("road", {{"preset", "road"}, {"effects", {{"specularAntiAliasing", false}}}});
  EXPECT_TRUE(contains(fragment(on), "= wg_specular_aa("));
  EXPECT_FALSE(contains(fragment(off), "wg_specular_aa("));
  EXPECT_FALSE(contains(fragment(off), "dFdx("));
  EXPECT_FALSE(contains(fragment(off, ShaderLanguage::Hlsl), "ddx("));
  EXPECT_TRUE(contains(fragment(off), "= wg_wet_roughness("));
}

// Everything beyond the seed off, and eq. 3.1's wind term too (a constant spirv-opt
// folds): the weather's cheapest complete form still compiles to valid SPIR-V in both
// languages.
TEST(WeatherLooksSwitch, TheLeanWeatherCompilesAndItsReflectionSaysWhatIsOff) {
  json lean = rockWith({{"relief", false}, {"ripple", false}, {"specularAntiAliasing", false}, {"skyExposure", false}});
  lean["terms"] = {1, 1, 1, 0};
  CompiledMaterial m = compiled("rock", lean);
  for (const auto& stage : m.stages) EXPECT_FALSE(stage.spirv.empty());
  std::string text = fragment(m);
  for (const char* gone : {"= wg_noise_relief(", "= wg_wet_normal(", "wg_specular_aa(", "textureGather("})
    EXPECT_FALSE(contains(text, gone)) << gone;
  json effects = json::parse(m.reflectionJson)["weather"]["effects"];
  EXPECT_EQ(effects["relief"], false);
  EXPECT_EQ(effects["ripple"], false);
  EXPECT_EQ(effects["specularAntiAliasing"], false);
  EXPECT_EQ(effects["snow"], true);
  json full = json::parse(compiled("rock", "rock").reflectionJson)["weather"]["effects"];
  EXPECT_EQ(full["relief"], true);
  EXPECT_EQ(full["ripple"], true);
  EXPECT_EQ(full["specularAntiAliasing"], true);
}

// rock.json's "quality" switch: its low variant drops the three looks.
TEST(WeatherLooksSwitch, RocksLowQualityVariantDropsTheLooks) {
  CompileResult low = compileMaterialFile(std::string(WG_SOURCE_DIR) + "/graphs/rock.json",
                                          {.switches = {{"quality", "low"}}});
  ASSERT_TRUE(low.material);
  std::string text = fragment(*low.material);
  EXPECT_FALSE(contains(text, "= wg_noise_relief("));
  EXPECT_FALSE(contains(text, "= wg_wet_normal("));
  EXPECT_FALSE(contains(text, "wg_specular_aa("));
  EXPECT_TRUE(contains(text, "= wg_snow_coverage("));
}

// Relief on a road (no snow or ice) changes no shader, so it is off in the reflection
// and the content hash: the variants share one file set, and the graph's own hash.
TEST(WeatherLooksSwitch, AnEffectThatChangesNoShaderSharesItsVariantsFiles) {
  json doc = json::parse(readFile(std::string(WG_SOURCE_DIR) + "/graphs/road.json"));
  doc["switches"] = {{"looks", {{"values", {"plain", "rich"}}, {"default", "rich"}}}};
  doc["weather"] = {{"preset", "road"}, {"effects", {{"relief", {{"switch", "looks"}, {"when", {"rich"}}}}}}};
  auto stem = [&](const std::string& looks) {
    CompileResult r = compileMaterialText("road.json", doc.dump(), {.hashKeyedFileStem = true, .switches = {{"looks", looks}}});
    EXPECT_TRUE(r.material);
    return r.material ? std::pair(r.material->fileStem, r.material->reflectionJson) : std::pair(std::string(), std::string());
  };
  auto [plain, plainReflection] = stem("plain");
  auto [rich, richReflection] = stem("rich");
  EXPECT_EQ(plain, rich);
  EXPECT_EQ(plainReflection, richReflection);
  EXPECT_FALSE(json::parse(richReflection)["weather"]["effects"]["relief"].get<bool>());
  doc.erase("switches");
  doc["weather"] = "road";
  CompileResult preset = compileMaterialText("road.json", doc.dump(), {.hashKeyedFileStem = true});
  ASSERT_TRUE(preset.material);
  EXPECT_EQ(preset.material->fileStem, rich);
}

}  // namespace
}  // namespace wg
