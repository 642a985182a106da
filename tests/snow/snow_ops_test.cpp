// CPU semantics of the snow layer's node ops (nodes/snow_ops.cpp), which the CPU
// evaluator and constant folding share with the emitted shaders.
#include <gtest/gtest.h>

#include <cmath>

#include "nodes/height_field.hpp"
#include "nodes/op_registry.hpp"

namespace wg {
namespace {

Value run(const char* op, std::vector<Value> inputs, const SurfacePoint& surface = {}, const FrameState& frame = {}) {
  const OpDef* def = findOp(op);
  EXPECT_NE(def, nullptr) << op;
  EvalContext c;
  c.surface = &surface;
  c.frame = &frame;
  return def->eval(inputs.data(), c);
}

TEST(SnowOps, BorderFadeIsEquations310And311) {
  FrameState f;
  f.cameraPosition = {10.f, 3.f, -2.f};
  auto fade = [&](float x, float z) {
    return run("snow_border_fade", {Value::vec3(x, 0.f, z), Value::scalar(14.f), Value::scalar(19.f)}, {}, f).x();
  };
  EXPECT_FLOAT_EQ(fade(10.f, -2.f), 1.f);         // under the camera
  EXPECT_FLOAT_EQ(fade(10.f + 13.9f, -2.f), 1.f);  // inside near
  EXPECT_FLOAT_EQ(fade(10.f, -2.f + 19.5f), 0.f);  // beyond far
  EXPECT_NEAR(fade(10.f + 16.5f, -2.f), 0.5f, 1e-5f);  // smoothstep's midpoint
  // Only xz counts (eq. 3.10): height does not fade.
  EXPECT_FLOAT_EQ(run("snow_border_fade", {Value::vec3(10.f, 50.f, -2.f), Value::scalar(14.f), Value::scalar(19.f)}, {}, f).x(), 1.f);
}

TEST(SnowOps, GlitterOnlyInTheHighlightAndNeverInShadow) {
  FrameState f;
  f.sunDirection = {0.f, 0.6f, 0.8f};
  f.sunIntensity = 1.f;
  f.cameraPosition = {0.f, 6.f, -8.f};  // the mirror direction of the sun about +y
  SurfacePoint lit, shadowed;
  shadowed.sunVisibility = 0.f;
  Value up = Value::vec3(0.f, 1.f, 0.f);
  auto glitter = [&](const Value& n, float x, float z, float sparkle, const SurfacePoint& s) {
    return run("snow_glitter", {n, Value::vec3(x, 0.f, z), Value::scalar(sparkle), Value::scalar(64.f),
                                Value::scalar(0.15f), Value::scalar(60.f)}, s, f).x();
  };
  // The brightest point of a 10 cm square, 0.5 mm apart: a sparkle's centre.
  float peak = 0.f, px = 0.f, pz = 0.f;
  for (int i = 0; i < 200; ++i)
    for (int j = 0; j < 200; ++j)
      if (float g = glitter(up, i * 5e-4f, j * 5e-4f, 1.f, lit); g > peak) peak = g, px = i * 5e-4f, pz = j * 5e-4f;
  EXPECT_NEAR(peak, 1.f, 0.02f);                     // N = H: the highlight's peak on a bump's peak
  EXPECT_EQ(glitter(up, px, pz, 0.f, lit), 0.f);       // the graph masks it off
  EXPECT_EQ(glitter(up, px, pz, 1.f, shadowed), 0.f);  // seed 3.5.2: never in shadow
  // Tilted 45 degrees away from the half vector: outside a shininess-64 highlight.
  EXPECT_LT(glitter(Value::vec3(0.7071f, 0.7071f, 0.f), px, pz, 1.f, lit), 1e-4f);
}

// The CPU's sparkles are the GPU's where a pixel is far under a cell (level 0): smooth
// bumps a quarter of a 1.7 cm cell in radius, fixed in the world, in `density` of the
// cells, so nothing pops where a point crosses a cell edge.
TEST(SnowOps, GlitterSparklesAreSmoothBumpsInDensityOfTheCells) {
  FrameState f;
  f.sunDirection = {0.f, 1.f, 0.f};
  f.sunIntensity = 1.f;
  f.cameraPosition = {0.f, 10.f, 0.f};
  SurfacePoint s;
  auto sparkles = [&](float x, float z) {
    return run("snow_glitter", {Value::vec3(0.f, 1.f, 0.f), Value::vec3(x, 0.f, z), Value::scalar(1.f),
                                Value::scalar(1.f), Value::scalar(0.15f), Value::scalar(60.f)}, s, f).x();
  };
  constexpr float kStep = 5e-4f;  // 0.5 mm: 33 samples per cell
  double sum = 0.0;
  float steepest = 0.f;
  int samples = 0;
  for (int i = 0; i < 1000; ++i) {
    float previous = sparkles(-0.25f, -0.25f + i * kStep);
    for (int j = 1; j < 1000; ++j, ++samples) {
      float v = sparkles(-0.25f + j * kStep, -0.25f + i * kStep);
      steepest = std::max(steepest, std::abs(v - previous));
      sum += v;
      previous = v;
    }
  }
  EXPECT_LT(steepest, 0.25f) << "a 4 mm bump changes by under 0.2 per half millimetre; a cell edge would jump by 1";
  // Each sparkle holds pi r^2 / 3 of a cell's area (r a quarter cell): 0.0654 times 0.15.
  EXPECT_NEAR(sum / samples, 0.15 * 0.06545, 0.2 * 0.15 * 0.06545);
}

TEST(SnowOps, DeformationReadsTheMapTexelAsHeightAndNormals) {
  SurfacePoint s;
  s.snowDeformation = {-0.12f, 0.3f, 0.9f, -0.1f};  // height, world normal
  Value v = run("snow_deformation", {Value::vec3(1.f, 2.f, 3.f), Value::scalar(40.96f)}, s);
  const OpDef* def = findOp("snow_deformation");
  EXPECT_FLOAT_EQ(applyAccessor(v, def->outputs[def->findOutput("height")].accessor).x(), -0.12f);
  Value tangent = applyAccessor(v, def->outputs[def->findOutput("normal")].accessor);
  // A level layer's tangent frame is (+x, +z, +y).
  EXPECT_FLOAT_EQ(tangent.v[0], 0.3f);
  EXPECT_FLOAT_EQ(tangent.v[1], -0.1f);
  EXPECT_FLOAT_EQ(tangent.v[2], 0.9f);
  Value world = applyAccessor(v, def->outputs[def->findOutput("worldNormal")].accessor);
  EXPECT_FLOAT_EQ(world.v[1], 0.9f);
}

// The terrain under the layer: the height map in metres, and the normal of its slope
// in the level layer's tangent frame (x along +x, y along +z, z up).
TEST(SnowOps, GroundIsTheTerrainMapInMetresWithItsSlope) {
  // A 3 x 3 map over 30 m rising 0.5 per unit along +x: 0, 0.5, 1, times 4 m.
  HeightField ramp{3, {0.f, 0.5f, 1.f, 0.f, 0.5f, 1.f, 0.f, 0.5f, 1.f}};
  FrameState f;
  f.terrainRegion = {-15.f, -15.f, 1.f / 30.f, 1.f / 30.f};
  f.terrainHeightScale = 4.f;
  EvalContext c;
  SurfacePoint surface;
  c.surface = &surface;
  c.frame = &f;
  c.terrainHeight = &ramp;
  const OpDef* def = findOp("snow_ground");
  ASSERT_NE(def, nullptr);
  Value at = Value::vec3(0.f, 7.f, 3.f);  // y does not matter
  Value v = def->eval(&at, c);
  auto output = [&](const char* name) { return applyAccessor(v, def->outputs[def->findOutput(name)].accessor); };
  EXPECT_NEAR(output("height").x(), 2.f, 1e-5f);  // the middle texel: 0.5 x 4 m
  // 2 m per 10 m along +x: the normal leans back against the slope, none along z.
  Value n = output("normal");
  float k = 1.f / std::sqrt(1.f + 0.04f);
  EXPECT_NEAR(n.v[0], -0.2f * k, 1e-4f);
  EXPECT_NEAR(n.v[1], 0.f, 1e-6f);
  EXPECT_NEAR(n.v[2], k, 1e-4f);
  EXPECT_NEAR(output("flatness").x(), k, 1e-4f);
  // No terrain bound: flat ground at 0.
  c.terrainHeight = nullptr;
  v = def->eval(&at, c);
  EXPECT_EQ(output("height").x(), 0.f);
  EXPECT_EQ(output("flatness").x(), 1.f);
}

}  // namespace
}  // namespace wg
