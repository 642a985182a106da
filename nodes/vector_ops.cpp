// Vector and colour ops: swizzle, split, combine, desaturate, constant.
#include "nodes/componentwise.hpp"
#include "nodes/op_registry.hpp"

namespace wg {

namespace {
// Rec. 709 luma weights, the usual definition of "grey" for linear RGB.
constexpr float kLumaR = 0.2126f, kLumaG = 0.7152f, kLumaB = 0.0722f;

Value combine(const Value* in, int width) {
  Value out{floatVectorOfWidth(width), {}};
  for (int i = 0; i < width; ++i) out.v[i] = in[i].x();
  return out;
}
PortSpec component(std::string_view name) { return {name, PortType::Float, Value::scalar(0.f)}; }
}  // namespace

void appendVectorOps(std::vector<OpDef>& ops) {
  ops.push_back({"constant", "vector", "a literal value, named for reuse", {{"value", PortType::Generic, std::nullopt}},
                 ValueRule::Generic, ValueType::Float, "{value}", "", singleOutput(),
                 [](const Value* in, const EvalContext&) { return in[0]; }});
  ops.push_back({"swizzle", "vector", "reorders components; channels is 1-4 of xyzw or rgba",
                 {{"in", PortType::Generic, std::nullopt}, {"channels", PortType::Text, std::nullopt}},
                 ValueRule::SwizzleText, ValueType::Float, "{in}{@channels}", "", singleOutput(),
                 [](const Value* in, const EvalContext& context) {
                   return applyAccessor(in[0], "." + std::string(context.text));
                 }});
  ops.push_back({"split", "vector", "separate components x, y, z, w (z and w need vec3/vec4)",
                 {{"in", PortType::Generic, std::nullopt}}, ValueRule::Generic, ValueType::Float, "{in}", "",
                 {{"x", ".x"}, {"y", ".y"}, {"z", ".z"}, {"w", ".w"}},
                 [](const Value* in, const EvalContext&) { return in[0]; }});
  ops.push_back({"combine2", "vector", "vec2(x, y)", {component("x"), component("y")}, ValueRule::Fixed,
                 ValueType::Vec2, "{T}({x}, {y})", "", singleOutput(),
                 [](const Value* in, const EvalContext&) { return combine(in, 2); }});
  ops.push_back({"combine3", "vector", "vec3(x, y, z)", {component("x"), component("y"), component("z")},
                 ValueRule::Fixed, ValueType::Vec3, "{T}({x}, {y}, {z})", "", singleOutput(),
                 [](const Value* in, const EvalContext&) { return combine(in, 3); }});
  ops.push_back({"combine4", "vector", "vec4(x, y, z, w)",
                 {component("x"), component("y"), component("z"), component("w")}, ValueRule::Fixed,
                 ValueType::Vec4, "{T}({x}, {y}, {z}, {w})", "", singleOutput(),
                 [](const Value* in, const EvalContext&) { return combine(in, 4); }});
  ops.push_back({"desaturate", "color", "blends a colour towards its Rec. 709 luminance by amount",
                 {{"color", PortType::Vec3, std::nullopt}, {"amount", PortType::Float, Value::scalar(1.f), 0.f, 1.f}},
                 ValueRule::Fixed, ValueType::Vec3,
                 "mix({color}, vec3(dot({color}, vec3(0.2126, 0.7152, 0.0722))), {amount})", "", singleOutput(),
                 [](const Value* in, const EvalContext&) {
                   const auto& c = in[0].v;
                   float luma = c[0] * kLumaR + c[1] * kLumaG + c[2] * kLumaB;
                   float t = in[1].x();
                   return Value::vec3(c[0] + (luma - c[0]) * t, c[1] + (luma - c[1]) * t, c[2] + (luma - c[2]) * t);
                 }});
}

}  // namespace wg
