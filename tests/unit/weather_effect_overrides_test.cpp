// Effects switched by the caller (CompileOptions::weatherEffects, the CLI's --effects)
// act exactly as the same switches written in the graph's "effects" block, apply only
// where the graph has weather, and an unknown name is WG4006 whatever the graph.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "driver/material_compiler.hpp"

namespace wg {
namespace {

using json = nlohmann::json;

std::string bundledGraph(const std::string& name) {
  std::ifstream in(std::string(WG_SOURCE_DIR) + "/graphs/" + name + ".json");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

CompileResult compileText(const std::string& name, const std::string& text, const WeatherEffectOverrides& effects) {
  CompileOptions options;
  options.emitSpirv = false;
  options.weatherEffects = effects;
  return compileMaterialText(name + ".json", text, options);
}

CompiledMaterial compiled(const std::string& name, const std::string& text, const WeatherEffectOverrides& effects = {}) {
  CompileResult r = compileText(name, text, effects);
  EXPECT_TRUE(r.material) << (r.diagnostics.empty() ? "" : r.diagnostics.items().front().message);
  return r.material ? std::move(*r.material) : CompiledMaterial{};
}

std::string fragment(const CompiledMaterial& m) { return m.stage(ShaderLanguage::Glsl, ShaderStage::Fragment).source; }
bool contains(const std::string& text, std::string_view piece) { return text.find(piece) != std::string::npos; }

TEST(WeatherEffectOverrides, AreTheSameAsEditingTheGraphsEffects) {
  // rock.json switches relief and specular AA with its "quality" switch; the overrides
  // replace that, as an edited block does.
  json edited = json::parse(bundledGraph("rock"));
  edited["weather"]["effects"]["relief"] = false;
  edited["weather"]["effects"]["specularAntiAliasing"] = false;
  CompiledMaterial byGraph = compiled("rock", edited.dump());
  CompiledMaterial byOverride = compiled("rock", bundledGraph("rock"), {{"relief", false}, {"specularAntiAliasing", false}});
  CompiledMaterial plain = compiled("rock", bundledGraph("rock"));
  EXPECT_NE(byOverride.contentHash, plain.contentHash);
  EXPECT_EQ(byOverride.contentHash, byGraph.contentHash);
  EXPECT_EQ(byOverride.reflectionJson, byGraph.reflectionJson);
  ASSERT_EQ(byOverride.stages.size(), byGraph.stages.size());
  for (std::size_t i = 0; i < byGraph.stages.size(); ++i) EXPECT_EQ(byOverride.stages[i].source, byGraph.stages[i].source);
  EXPECT_TRUE(contains(fragment(plain), "= wg_specular_aa("));
  EXPECT_FALSE(contains(fragment(byOverride), "wg_specular_aa("));
  EXPECT_FALSE(contains(fragment(byOverride), "= wg_noise_relief("));
  EXPECT_TRUE(contains(fragment(byOverride), "= wg_wet_normal("));  // ripple was not named
}

TEST(WeatherEffectOverrides, TheLastOneForAnEffectWins) {
  CompiledMaterial m = compiled("road", bundledGraph("road"), {{"ripple", false}, {"ripple", true}});
  EXPECT_TRUE(contains(fragment(m), "= wg_wet_normal("));
}

TEST(WeatherEffectOverrides, CanTurnAnEffectOnThatThePresetLacks) {
  EXPECT_FALSE(contains(fragment(compiled("road", bundledGraph("road"))), "= wg_snow_coverage("));
  EXPECT_TRUE(contains(fragment(compiled("road", bundledGraph("road"), {{"snow", true}})), "= wg_snow_coverage("));
}

TEST(WeatherEffectOverrides, GraphsWithoutWeatherIgnoreThem) {
  CompiledMaterial plain = compiled("snow_layer", bundledGraph("snow_layer"));
  CompiledMaterial overridden = compiled("snow_layer", bundledGraph("snow_layer"), {{"snow", true}, {"relief", false}});
  EXPECT_EQ(plain.contentHash, overridden.contentHash);
  EXPECT_EQ(fragment(plain), fragment(overridden));
}

TEST(WeatherEffectOverrides, AnUnknownNameIsWG4006WithAHintWhateverTheGraph) {
  for (const char* graph : {"rock", "snow_layer"}) {
    CompileResult r = compileText(graph, bundledGraph(graph), {{"relif", false}});
    EXPECT_FALSE(r.material) << graph;
    ASSERT_TRUE(r.diagnostics.contains(DiagCode::UnknownWeatherKey)) << graph;
    const Diagnostic& d = r.diagnostics.items().front();
    EXPECT_NE(d.message.find("unknown weather effect 'relif'"), std::string::npos) << d.message;
    EXPECT_NE(d.hint.find("relief"), std::string::npos) << d.hint;
    EXPECT_EQ(d.location.line, 0) << "an override has no place in the graph";
  }
}

}  // namespace
}  // namespace wg
