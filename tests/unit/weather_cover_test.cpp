// What weather layers do to what lies under them: a glowing panel under full snow shows
// snow, not its glow through it; under a puddle (water) it still glows. Rain wets by
// porosity: a dielectric darkens and turns glossy, a metal keeps its colour and a little
// roughness.
#include <gtest/gtest.h>

#include "compiler/cpu_evaluator.hpp"
#include "driver/material_compiler.hpp"

namespace wg {
namespace {

// A pink emissive panel with a weather preset.
CpuEvaluator glowingPanel(const std::string& preset = "rock") {
  const std::string graph = R"({"name": "panel", "nodes": [],
    "output": {"baseColor": [0.2, 0.2, 0.2], "emissive": [4.0, 0.5, 2.0], "roughness": 0.4},
    "weather": {"preset": ")" + preset + R"("}})";
  DiagnosticList diagnostics;
  auto ir = buildOptimizedIr("panel.json", graph, diagnostics);
  EXPECT_TRUE(ir.has_value());
  return CpuEvaluator(std::move(*ir));
}

EvalInputs levelGround() {
  EvalInputs in;
  in.surface.worldNormal = {0.f, 1.f, 0.f};
  in.frame.temperature = -6.f;
  in.frame.sunDirection = {0.f, 1.f, 0.f};
  return in;
}

TEST(WeatherCover, FullSnowHidesTheGlow) {
  CpuEvaluator panel = glowingPanel();
  EvalInputs dry = levelGround();
  EXPECT_EQ(panel.evaluate(dry).output(PbrField::Emissive).v[0], 4.f);
  EvalInputs snowy = levelGround();
  snowy.frame.snowLevel = 1.f;
  snowy.frame.sunMelt = 0.f;
  EvalResult r = panel.evaluate(snowy);
  ASSERT_GT(r.coverageOf(CoverageTerm::Snow), 0.99f);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(r.output(PbrField::Emissive).v[c], 0.f, 1e-3f);
  const Value& snow = r.output(PbrField::BaseColor);
  EXPECT_GT(snow.v[0], 0.8f);  // white, not tinted by the glow
  EXPECT_NEAR(snow.v[0], snow.v[2], 0.05f);
}

TEST(WeatherCover, WaterKeepsTheGlow) {
  CpuEvaluator panel = glowingPanel("road");  // a preset with puddles
  EvalInputs flooded = levelGround();
  flooded.frame.temperature = 12.f;
  flooded.frame.puddleLevel = 1.f;
  flooded.frame.wetnessLevel = 1.f;
  // Puddles form in the noise's hollows: walk along x to one.
  EvalResult r = panel.evaluate(flooded);
  for (float x = 0.f; x < 32.f && r.coverageOf(CoverageTerm::Puddle) < 0.9f; x += 0.25f) {
    flooded.surface.worldPosition = {x, 0.f, 0.f};
    r = panel.evaluate(flooded);
  }
  ASSERT_GT(r.coverageOf(CoverageTerm::Puddle), 0.9f);
  EXPECT_EQ(r.output(PbrField::Emissive).v[0], 4.f);
}

TEST(WeatherCover, RainWetsByPorosity) {
  const std::string graph = R"({"name": "metal", "nodes": [],
    "output": {"baseColor": [0.9, 0.6, 0.3], "metallic": 1.0, "roughness": 0.4}, "weather": {"preset": "rock"}})";
  DiagnosticList diagnostics;
  auto ir = buildOptimizedIr("metal.json", graph, diagnostics);
  ASSERT_TRUE(ir.has_value());
  CpuEvaluator metal(std::move(*ir));
  EvalInputs rain = levelGround();
  rain.frame.temperature = 12.f;
  rain.frame.wetnessLevel = 1.f;
  rain.frame.precipitation = 1.f;
  EvalResult wet = metal.evaluate(rain);
  ASSERT_GT(wet.coverageOf(CoverageTerm::Wet), 0.9f);
  EXPECT_NEAR(wet.output(PbrField::BaseColor).v[0], 0.9f, 1e-4f);  // not darkened
  EXPECT_NEAR(wet.output(PbrField::Roughness).v[0], 0.15f, 1e-4f);  // a film, not a mirror
  CpuEvaluator panel = glowingPanel();  // a dielectric: eq. 3.16-3.17 as printed
  EvalResult soaked = panel.evaluate(rain);
  EXPECT_NEAR(soaked.output(PbrField::BaseColor).v[0], 0.2f * 0.7f, 1e-3f);
  EXPECT_NEAR(soaked.output(PbrField::Roughness).v[0], 0.f, 1e-4f);
}

}  // namespace
}  // namespace wg
