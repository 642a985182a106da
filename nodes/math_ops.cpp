// Maths ops. Generic ports take float..vec4; the shader writer splats scalars to T
// before they reach these templates, so every template sees matching widths.
#include <cmath>

#include "nodes/componentwise.hpp"
#include "nodes/op_registry.hpp"

namespace wg {

namespace {
constexpr auto G = PortType::Generic;
constexpr auto F = PortType::Float;

PortSpec gen(std::string_view name, float dflt) { return {name, G, Value::scalar(dflt)}; }
PortSpec genRequired(std::string_view name) { return {name, G, std::nullopt}; }

// Robust forms: the shader and the CPU agree even on degenerate inputs (negative
// bases, zero vectors), where the raw GLSL/HLSL intrinsics are undefined.
float safePow(float base, float exponent) { return std::pow(std::max(base, 0.f), exponent); }
float safeSqrt(float x) { return std::sqrt(std::max(x, 0.f)); }
float fractional(float x) { return x - std::floor(x); }
float smoothStep(float e0, float e1, float x) {
  float t = std::clamp((x - e0) / (e1 - e0), 0.f, 1.f);
  return t * t * (3.f - 2.f * t);
}
// Below this squared length a vector counts as zero and normalises to zero.
constexpr float kMinSquaredLength = 1e-12f;

OpDef binary(std::string_view name, std::string_view summary, std::string_view glsl,
             std::string_view hlsl, float defaultA, float defaultB, CpuEval eval) {
  return {name, "math", summary, {gen("a", defaultA), gen("b", defaultB)}, ValueRule::Generic,
          ValueType::Float, glsl, hlsl, singleOutput(), eval};
}

OpDef unary(std::string_view name, std::string_view summary, std::string_view glsl,
            std::string_view hlsl, CpuEval eval) {
  return {name, "math", summary, {genRequired("in")}, ValueRule::Generic, ValueType::Float, glsl,
          hlsl, singleOutput(), eval};
}
}  // namespace

void appendMathOps(std::vector<OpDef>& ops) {
  const std::size_t first = ops.size();
  ops.push_back(binary("add", "a + b", "({a} + {b})", "", 0.f, 0.f, [](const Value* in, const EvalContext&) {
    return mapComponents(in[0], in[1], [](float a, float b) { return a + b; });
  }));
  ops.push_back(binary("subtract", "a - b", "({a} - {b})", "", 0.f, 0.f, [](const Value* in, const EvalContext&) {
    return mapComponents(in[0], in[1], [](float a, float b) { return a - b; });
  }));
  ops.push_back(binary("multiply", "a * b, component-wise", "({a} * {b})", "", 1.f, 1.f,
                       [](const Value* in, const EvalContext&) {
                         return mapComponents(in[0], in[1], [](float a, float b) { return a * b; });
                       }));
  ops.push_back(binary("divide", "a / b, component-wise", "({a} / {b})", "", 1.f, 1.f,
                       [](const Value* in, const EvalContext&) {
                         return mapComponents(in[0], in[1], [](float a, float b) { return a / b; });
                       }));
  ops.push_back(binary("min", "component-wise minimum", "min({a}, {b})", "", 0.f, 0.f,
                       [](const Value* in, const EvalContext&) {
                         return mapComponents(in[0], in[1], [](float a, float b) { return std::min(a, b); });
                       }));
  ops.push_back(binary("max", "component-wise maximum", "max({a}, {b})", "", 0.f, 0.f,
                       [](const Value* in, const EvalContext&) {
                         return mapComponents(in[0], in[1], [](float a, float b) { return std::max(a, b); });
                       }));
  ops.push_back({"pow", "math", "max(base, 0) ^ exponent (negative bases clamp to 0)",
                 {genRequired("base"), gen("exponent", 1.f)}, ValueRule::Generic, ValueType::Float,
                 "pow(max({base}, 0.0), {exponent})", "", singleOutput(),
                 [](const Value* in, const EvalContext&) { return mapComponents(in[0], in[1], safePow); }});
  ops.push_back({"step", "math", "0 where x < edge, else 1", {gen("edge", 0.5f), genRequired("x")},
                 ValueRule::Generic, ValueType::Float, "step({edge}, {x})", "", singleOutput(),
                 [](const Value* in, const EvalContext&) {
                   return mapComponents(in[0], in[1], [](float e, float x) { return x < e ? 0.f : 1.f; });
                 }});

  ops.push_back(unary("abs", "|x|", "abs({in})", "", [](const Value* in, const EvalContext&) {
    return mapComponents(in[0], [](float x) { return std::fabs(x); });
  }));
  ops.push_back(unary("negate", "-x", "(-{in})", "", [](const Value* in, const EvalContext&) {
    return mapComponents(in[0], [](float x) { return -x; });
  }));
  ops.push_back(unary("one_minus", "1 - x", "(1.0 - {in})", "", [](const Value* in, const EvalContext&) {
    return mapComponents(in[0], [](float x) { return 1.f - x; });
  }));
  ops.push_back(unary("floor", "largest integer <= x", "floor({in})", "", [](const Value* in, const EvalContext&) {
    return mapComponents(in[0], [](float x) { return std::floor(x); });
  }));
  ops.push_back(unary("frac", "x - floor(x)", "fract({in})", "", [](const Value* in, const EvalContext&) {
    return mapComponents(in[0], fractional);
  }));
  ops.push_back(unary("sqrt", "square root of max(x, 0)", "sqrt(max({in}, 0.0))", "",
                      [](const Value* in, const EvalContext&) { return mapComponents(in[0], safeSqrt); }));
  ops.push_back(unary("sin", "sine (radians)", "sin({in})", "", [](const Value* in, const EvalContext&) {
    return mapComponents(in[0], [](float x) { return std::sin(x); });
  }));
  ops.push_back(unary("cos", "cosine (radians)", "cos({in})", "", [](const Value* in, const EvalContext&) {
    return mapComponents(in[0], [](float x) { return std::cos(x); });
  }));
  ops.push_back(unary("saturate", "clamp(x, 0, 1)", "clamp({in}, 0.0, 1.0)", "",
                      [](const Value* in, const EvalContext&) {
                        return mapComponents(in[0], [](float x) { return std::clamp(x, 0.f, 1.f); });
                      }));

  ops.push_back({"clamp", "math", "min(max(x, low), high)", {genRequired("x"), gen("low", 0.f), gen("high", 1.f)},
                 ValueRule::Generic, ValueType::Float, "clamp({x}, {low}, {high})", "", singleOutput(),
                 [](const Value* in, const EvalContext&) {
                   return mapComponents(in[0], in[1], in[2],
                                        [](float x, float lo, float hi) { return std::min(std::max(x, lo), hi); });
                 }});
  ops.push_back({"lerp", "math", "a + (b - a) * t", {gen("a", 0.f), gen("b", 1.f), genRequired("t")},
                 ValueRule::Generic, ValueType::Float, "mix({a}, {b}, {t})", "",
                 singleOutput(), [](const Value* in, const EvalContext&) {
                   return mapComponents(in[0], in[1], in[2], [](float a, float b, float t) { return a + (b - a) * t; });
                 }});
  ops.push_back({"smoothstep", "math", "Hermite step of x between edge0 and edge1",
                 {gen("edge0", 0.f), gen("edge1", 1.f), genRequired("x")}, ValueRule::Generic, ValueType::Float,
                 "smoothstep({edge0}, {edge1}, {x})", "", singleOutput(),
                 [](const Value* in, const EvalContext&) { return mapComponents(in[0], in[1], in[2], smoothStep); }});
  ops.push_back({"remap", "math", "maps x from [inLow, inHigh] to [outLow, outHigh], unclamped",
                 {genRequired("x"), gen("inLow", 0.f), gen("inHigh", 1.f), gen("outLow", 0.f), gen("outHigh", 1.f)},
                 ValueRule::Generic, ValueType::Float,
                 "({outLow} + ({x} - {inLow}) / ({inHigh} - {inLow}) * ({outHigh} - {outLow}))", "",
                 singleOutput(), [](const Value* in, const EvalContext&) {
                   Value out{widestType({&in[0], &in[1], &in[2], &in[3], &in[4]}), {}};
                   for (int i = 0; i < out.width(); ++i)
                     out.v[i] = in[3].at(i) + (in[0].at(i) - in[1].at(i)) / (in[2].at(i) - in[1].at(i)) *
                                                  (in[4].at(i) - in[3].at(i));
                   return out;
                 }});

  ops.push_back({"dot", "math", "dot product", {genRequired("a"), genRequired("b")}, ValueRule::Fixed,
                 ValueType::Float, "dot({a}, {b})", "", singleOutput(),
                 [](const Value* in, const EvalContext&) { return Value::scalar(dotProduct(in[0], in[1])); }});
  ops.push_back({"length", "math", "Euclidean length", {genRequired("in")}, ValueRule::Fixed, ValueType::Float,
                 "length({in})", "", singleOutput(),
                 [](const Value* in, const EvalContext&) { return Value::scalar(std::sqrt(dotProduct(in[0], in[0]))); }});
  ops.push_back({"normalize", "math", "unit vector; a zero vector stays zero", {genRequired("in")},
                 ValueRule::Generic, ValueType::Float,
                 "({in} * inversesqrt(max(dot({in}, {in}), 1e-12)))", "", singleOutput(),
                 [](const Value* in, const EvalContext&) {
                   float scale = 1.f / std::sqrt(std::max(dotProduct(in[0], in[0]), kMinSquaredLength));
                   return mapComponents(in[0], [scale](float x) { return x * scale; });
                 }});
  ops.push_back({"cross", "math", "cross product of two vec3",
                 {{"a", PortType::Vec3, std::nullopt}, {"b", PortType::Vec3, std::nullopt}}, ValueRule::Fixed, ValueType::Vec3,
                 "cross({a}, {b})", "", singleOutput(), [](const Value* in, const EvalContext&) {
                   const auto& a = in[0].v;
                   const auto& b = in[1].v;
                   return Value::vec3(a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]);
                 }});

  ops.push_back({"greater", "math", "a > b, as bool", {{"a", F, std::nullopt}, {"b", F, Value::scalar(0.f)}},
                 ValueRule::Fixed, ValueType::Bool, "({a} > {b})", "", singleOutput(),
                 [](const Value* in, const EvalContext&) { return Value::boolean(in[0].x() > in[1].x()); }});
  ops.push_back({"less", "math", "a < b, as bool", {{"a", F, std::nullopt}, {"b", F, Value::scalar(0.f)}},
                 ValueRule::Fixed, ValueType::Bool, "({a} < {b})", "", singleOutput(),
                 [](const Value* in, const EvalContext&) { return Value::boolean(in[0].x() < in[1].x()); }});
  ops.push_back({"select", "math", "ifTrue where condition holds, else ifFalse",
                 {{"condition", PortType::Bool, std::nullopt}, genRequired("ifTrue"), genRequired("ifFalse")},
                 ValueRule::Generic, ValueType::Float, "({condition} ? {ifTrue} : {ifFalse})", "", singleOutput(),
                 [](const Value* in, const EvalContext&) { return in[0].asBool() ? in[1] : in[2]; }});
  // Functions of their inputs alone: the same in either stage.
  for (std::size_t i = first; i < ops.size(); ++i) ops[i].rate = OpRate::Any;
}

}  // namespace wg
