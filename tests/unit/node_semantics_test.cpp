// Every op's CPU semantics against values computed by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "nodes/lattice_noise.hpp"
#include "nodes/op_registry.hpp"

namespace wg {
namespace {

Value eval(std::string_view opName, std::vector<Value> inputs, std::string_view text = "",
           const SurfacePoint* surface = nullptr, const FrameState* frame = nullptr) {
  const OpDef* op = findOp(opName);
  EXPECT_NE(op, nullptr) << opName;
  EvalContext context;
  context.text = text;
  context.surface = surface;
  context.frame = frame;
  return op->eval(inputs.data(), context);
}

void expectValue(const Value& actual, const Value& expected, float tolerance = 1e-6f) {
  ASSERT_EQ(actual.type, expected.type);
  for (int i = 0; i < expected.width(); ++i) EXPECT_NEAR(actual.v[i], expected.v[i], tolerance) << "component " << i;
}

TEST(NodeSemantics, Arithmetic) {
  expectValue(eval("add", {Value::vec2(1, 2), Value::vec2(3, 5)}), Value::vec2(4, 7));
  expectValue(eval("subtract", {Value::scalar(1), Value::scalar(3)}), Value::scalar(-2));
  expectValue(eval("multiply", {Value::vec3(1, 2, 3), Value::vec3(2, 2, 2)}), Value::vec3(2, 4, 6));
  expectValue(eval("divide", {Value::vec2(1, 3), Value::vec2(4, 2)}), Value::vec2(0.25f, 1.5f));
  expectValue(eval("negate", {Value::scalar(2)}), Value::scalar(-2));
  expectValue(eval("one_minus", {Value::vec2(0.25f, 1)}), Value::vec2(0.75f, 0));
}

TEST(NodeSemantics, LerpClampSaturateMinMax) {
  expectValue(eval("lerp", {Value::scalar(2), Value::scalar(6), Value::scalar(0.25f)}), Value::scalar(3));
  expectValue(eval("lerp", {Value::vec2(0, 10), Value::vec2(1, 20), Value::vec2(0.5f, 0.1f)}), Value::vec2(0.5f, 11));
  expectValue(eval("clamp", {Value::vec3(-1, 0.5f, 2), Value::vec3(0, 0, 0), Value::vec3(1, 1, 1)}), Value::vec3(0, 0.5f, 1));
  expectValue(eval("saturate", {Value::vec2(-0.5f, 1.5f)}), Value::vec2(0, 1));
  expectValue(eval("min", {Value::vec2(1, 5), Value::vec2(3, 2)}), Value::vec2(1, 2));
  expectValue(eval("max", {Value::vec2(1, 5), Value::vec2(3, 2)}), Value::vec2(3, 5));
}

TEST(NodeSemantics, PowAbsFloorFracSqrt) {
  expectValue(eval("pow", {Value::scalar(2), Value::scalar(3)}), Value::scalar(8));
  expectValue(eval("pow", {Value::scalar(-2), Value::scalar(2)}), Value::scalar(0));  // negative bases clamp to 0
  expectValue(eval("abs", {Value::vec2(-1.5f, 2)}), Value::vec2(1.5f, 2));
  expectValue(eval("floor", {Value::vec2(-1.5f, 2.7f)}), Value::vec2(-2, 2));
  expectValue(eval("frac", {Value::vec2(-1.25f, 2.75f)}), Value::vec2(0.75f, 0.75f));
  expectValue(eval("sqrt", {Value::vec2(16, -4)}), Value::vec2(4, 0));
}

TEST(NodeSemantics, VectorMaths) {
  expectValue(eval("dot", {Value::vec3(1, 2, 3), Value::vec3(4, -5, 6)}), Value::scalar(12));
  expectValue(eval("cross", {Value::vec3(1, 0, 0), Value::vec3(0, 1, 0)}), Value::vec3(0, 0, 1));
  expectValue(eval("cross", {Value::vec3(0, 1, 0), Value::vec3(1, 0, 0)}), Value::vec3(0, 0, -1));
  expectValue(eval("normalize", {Value::vec3(3, 0, 4)}), Value::vec3(0.6f, 0, 0.8f));
  expectValue(eval("normalize", {Value::vec3(0, 0, 0)}), Value::vec3(0, 0, 0));  // zero stays zero
  expectValue(eval("length", {Value::vec2(3, 4)}), Value::scalar(5));
}

TEST(NodeSemantics, StepSmoothstepSinCosRemap) {
  expectValue(eval("step", {Value::scalar(0.5f), Value::scalar(0.4f)}), Value::scalar(0));
  expectValue(eval("step", {Value::scalar(0.5f), Value::scalar(0.5f)}), Value::scalar(1));
  // smoothstep(0, 1, 0.25) = 0.25^2 (3 - 0.5) = 0.15625
  expectValue(eval("smoothstep", {Value::scalar(0), Value::scalar(1), Value::scalar(0.25f)}), Value::scalar(0.15625f));
  expectValue(eval("smoothstep", {Value::scalar(0), Value::scalar(1), Value::scalar(2)}), Value::scalar(1));
  expectValue(eval("sin", {Value::scalar(1.57079632679f)}), Value::scalar(1));
  expectValue(eval("cos", {Value::scalar(0)}), Value::scalar(1));
  // remap 0.75 from [0.5, 1] to [10, 20] = 15
  expectValue(eval("remap", {Value::scalar(0.75f), Value::scalar(0.5f), Value::scalar(1), Value::scalar(10), Value::scalar(20)}),
              Value::scalar(15));
}

TEST(NodeSemantics, SwizzleSplitCombineDesaturate) {
  expectValue(eval("swizzle", {Value::vec4(1, 2, 3, 4), Value::scalar(0)}, "wzx"), Value::vec3(4, 3, 1));
  expectValue(eval("swizzle", {Value::vec3(1, 2, 3), Value::scalar(0)}, "bg"), Value::vec2(3, 2));
  expectValue(eval("combine3", {Value::scalar(1), Value::scalar(2), Value::scalar(3)}), Value::vec3(1, 2, 3));
  expectValue(eval("combine2", {Value::scalar(1), Value::scalar(2)}), Value::vec2(1, 2));
  expectValue(eval("combine4", {Value::scalar(1), Value::scalar(2), Value::scalar(3), Value::scalar(4)}), Value::vec4(1, 2, 3, 4));
  expectValue(applyAccessor(eval("split", {Value::vec3(7, 8, 9)}), ".z"), Value::scalar(9));
  // Rec. 709 luma of (1, 0, 0) is 0.2126; full desaturation gives grey at that level.
  expectValue(eval("desaturate", {Value::vec3(1, 0, 0), Value::scalar(1)}), Value::vec3(0.2126f, 0.2126f, 0.2126f));
  expectValue(eval("desaturate", {Value::vec3(1, 0, 0), Value::scalar(0)}), Value::vec3(1, 0, 0));
}

TEST(NodeSemantics, SelectAndComparisons) {
  expectValue(eval("greater", {Value::scalar(2), Value::scalar(1)}), Value::boolean(true));
  expectValue(eval("less", {Value::scalar(2), Value::scalar(1)}), Value::boolean(false));
  expectValue(eval("select", {Value::boolean(true), Value::scalar(3), Value::scalar(4)}), Value::scalar(3));
  expectValue(eval("select", {Value::boolean(false), Value::scalar(3), Value::scalar(4)}), Value::scalar(4));
}

TEST(NodeSemantics, GeometryReadsTheSurface) {
  SurfacePoint s;
  s.texcoord = {0.25f, 0.75f};
  s.worldPosition = {1, 2, 3};
  FrameState f;
  f.time = 4;
  expectValue(eval("texcoord", {}, "", &s, &f), Value::vec2(0.25f, 0.75f));
  expectValue(eval("world_position", {}, "", &s, &f), Value::vec3(1, 2, 3));
  expectValue(eval("time", {}, "", &s, &f), Value::scalar(4));
  // Panner(h, v, time): uv + (h, v) * time.
  expectValue(eval("panner", {Value::vec2(0.5f, 0.5f), Value::vec2(0.1f, -0.2f)}, "", &s, &f), Value::vec2(0.9f, -0.3f));
}

TEST(NodeSemantics, NormalMaps) {
  // A flat texel (0.5, 0.5, 1) unpacks to +Z.
  expectValue(eval("normal_unpack", {Value::vec3(0.5f, 0.5f, 1), Value::scalar(1)}), Value::vec3(0, 0, 1));
  // Texel (1, 0.5, 0.5) -> (1, 0, 0).
  expectValue(eval("normal_unpack", {Value::vec3(1, 0.5f, 0.5f), Value::scalar(1)}), Value::vec3(1, 0, 0));
  // RNM: a flat base leaves the detail unchanged.
  Value detail = Value::vec3(0.6f, 0, 0.8f);
  expectValue(eval("normal_blend", {Value::vec3(0, 0, 1), detail}), detail, 1e-5f);
  // RNM: a flat detail returns the base.
  Value base = Value::vec3(0, 0.6f, 0.8f);
  expectValue(eval("normal_blend", {base, Value::vec3(0, 0, 1)}), base, 1e-5f);
}

TEST(NodeSemantics, NoiseIsDeterministicAndInRange) {
  // On lattice points value noise equals the cell's hash.
  float n = valueNoise(3, -7);
  EXPECT_FLOAT_EQ(n, static_cast<float>(latticeHash(3, -7) >> 8) / 16777216.0f);
  EXPECT_FLOAT_EQ(gradientNoise(5, 9), 0.5f);  // gradient noise is 0.5 at lattice points
  for (int i = 0; i < 1000; ++i) {
    float x = i * 0.137f - 60.f, y = i * 0.071f - 30.f;
    float v = valueNoise(x, y), g = gradientNoise(x, y);
    EXPECT_GE(v, 0.f);
    EXPECT_LE(v, 1.f);
    EXPECT_GE(g, 0.f);
    EXPECT_LE(g, 1.f);
  }
  // The op scales its input first.
  expectValue(eval("value_noise", {Value::vec2(1.5f, 2.5f), Value::scalar(2)}), Value::scalar(valueNoise(3, 5)));
  // Known value pins the hash: any change to it changes every shader and must be deliberate.
  EXPECT_EQ(latticeHash(0, 0), 0u);
  EXPECT_EQ(latticeHash(1, 0), 1597334673u * 1597334673u);
}

}  // namespace
}  // namespace wg
