// Quality tiers (compiler/quality_tiers.hpp): a tier switches sky exposure and the looks
// over the preset; the caller's tier beats the graph's "quality", which beats the
// targets' default; the graph's own effects and --effects switch after the tier; and a
// tier that is unknown or not a string is a diagnostic at its JSON pointer.
#include <gtest/gtest.h>

#include <string>

#include "driver/material_compiler.hpp"

namespace wg {
namespace {

std::string roadGraph(const std::string& weather) {
  return R"({"name": "road", "nodes": [], "output": {"baseColor": 0.3, "roughness": 0.6}, "weather": )" + weather + "}";
}

CompileResult compile(const std::string& text, const QualityChoice& quality, const WeatherEffectOverrides& effects = {}) {
  CompileOptions options;
  options.emitSpirv = false;
  options.quality = quality;
  options.weatherEffects = effects;
  return compileMaterialText("road.json", text, options);
}

WeatherConfig weatherOf(const std::string& text, const QualityChoice& quality,
                        const WeatherEffectOverrides& effects = {}) {
  CompileResult r = compile(text, quality, effects);
  EXPECT_TRUE(r.material) << (r.diagnostics.empty() ? "" : r.diagnostics.items().front().message);
  return r.material ? r.material->ir.weather : WeatherConfig{};
}

TEST(QualityTiers, EachTierAddsToTheOneBefore) {
  const std::string road = roadGraph(R"("road")");
  const WeatherConfig low = weatherOf(road, {.requested = "low"});
  const WeatherConfig medium = weatherOf(road, {.requested = "medium"});
  const WeatherConfig high = weatherOf(road, {.requested = "high"});
  EXPECT_EQ(low.quality, "low");
  EXPECT_FALSE(low.effects.skyExposure);
  EXPECT_FALSE(low.effects.ripple || low.effects.relief || low.effects.specularAntiAliasing);
  EXPECT_TRUE(medium.effects.skyExposure);
  EXPECT_FALSE(medium.effects.ripple || medium.effects.relief || medium.effects.specularAntiAliasing);
  EXPECT_TRUE(high.effects.skyExposure && high.effects.ripple && high.effects.specularAntiAliasing);
  EXPECT_FALSE(high.effects.relief);  // a road has no snow or ice to give relief
  // The preset's own layers stay whatever the tier.
  EXPECT_TRUE(low.effects.wetness && low.effects.puddles && low.effects.hoarfrost);
}

TEST(QualityTiers, TheTierChangesTheShaders) {
  const std::string road = roadGraph(R"("road")");
  CompileResult low = compile(road, {.requested = "low"}), high = compile(road, {.requested = "high"});
  ASSERT_TRUE(low.material && high.material);
  const auto fragment = [](const CompileResult& r) {
    return r.material->stage(ShaderLanguage::Glsl, ShaderStage::Fragment).source;
  };
  EXPECT_LT(fragment(low).size(), fragment(high).size());
  EXPECT_EQ(fragment(low).find("wg_sky_exposure"), std::string::npos);
  EXPECT_NE(fragment(high).find("wg_sky_exposure"), std::string::npos);
}

TEST(QualityTiers, TheCallerBeatsTheGraphWhichBeatsTheTargetsDefault) {
  const std::string graph = roadGraph(R"({"preset": "road", "quality": "medium"})");
  EXPECT_EQ(weatherOf(graph, {.fallback = "low"}).quality, "medium");
  EXPECT_EQ(weatherOf(graph, {.requested = "low", .fallback = "high"}).quality, "low");
  EXPECT_EQ(weatherOf(roadGraph(R"("road")"), {.fallback = "low"}).quality, "low");
  EXPECT_EQ(weatherOf(roadGraph(R"("road")"), {}).quality, "high");
}

TEST(QualityTiers, TheGraphsEffectsAndTheCallersSwitchAfterTheTier) {
  const std::string graph = roadGraph(R"({"preset": "road", "quality": "low", "effects": {"ripple": true}})");
  const WeatherConfig w = weatherOf(graph, {}, {{"skyExposure", true}});
  EXPECT_EQ(w.quality, "low");
  EXPECT_TRUE(w.effects.ripple);       // the graph's own
  EXPECT_TRUE(w.effects.skyExposure);  // the caller's --effects
  EXPECT_FALSE(w.effects.relief);      // the tier's
}

TEST(QualityTiers, AnUnknownTierIsWG4006AtItsPointerWithAHint) {
  CompileResult r = compile(roadGraph(R"({"preset": "road", "quality": "mediun"})"), {});
  ASSERT_FALSE(r.material);
  const Diagnostic& d = r.diagnostics.items().front();
  EXPECT_EQ(d.code, DiagCode::UnknownWeatherKey);
  EXPECT_NE(d.message.find("quality tier 'mediun'"), std::string::npos) << d.message;
  EXPECT_NE(d.hint.find("medium"), std::string::npos) << d.hint;
  EXPECT_GT(d.location.line, 0);

  r = compile(roadGraph(R"("road")"), {.requested = "ultra"});
  ASSERT_FALSE(r.material);
  EXPECT_EQ(r.diagnostics.items().front().code, DiagCode::UnknownWeatherKey);
}

TEST(QualityTiers, ATierThatIsNotAStringIsWG4007) {
  CompileResult r = compile(roadGraph(R"({"preset": "road", "quality": 2})"), {});
  ASSERT_FALSE(r.material);
  EXPECT_EQ(r.diagnostics.items().front().code, DiagCode::WeatherSettingKind);
  EXPECT_NE(r.diagnostics.items().front().message.find("quality"), std::string::npos);
}

}  // namespace
}  // namespace wg
