// What an opaque weather layer does to what lies under it: a glowing panel under full
// snow shows snow, not its glow through it; under a puddle (water) it still glows.
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

}  // namespace
}  // namespace wg
