// CPU semantics of the snow layer's node ops (nodes/snow_ops.cpp), which the CPU
// evaluator and constant folding share with the emitted shaders.
#include <gtest/gtest.h>

#include <cmath>

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
  Value up = Value::vec3(0.f, 1.f, 0.f), origin = Value::vec3(0.f, 0.f, 0.f);
  auto glitter = [&](const Value& n, float sparkle, const SurfacePoint& s) {
    return run("snow_glitter", {n, origin, Value::scalar(sparkle), Value::scalar(64.f)}, s, f).x();
  };
  EXPECT_NEAR(glitter(up, 1.f, lit), 1.f, 1e-4f);  // N = H: the highlight's peak
  EXPECT_EQ(glitter(up, 0.f, lit), 0.f);           // no crystal there
  EXPECT_EQ(glitter(up, 1.f, shadowed), 0.f);      // seed 3.5.2: never in shadow
  // Tilted 45 degrees away from the half vector: outside a shininess-64 highlight.
  EXPECT_LT(glitter(Value::vec3(0.7071f, 0.7071f, 0.f), 1.f, lit), 1e-4f);
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

}  // namespace
}  // namespace wg
