// Ops that read the surface being shaded, the frame time or a material parameter.
// They are never constant-folded; the CPU evaluator reads them from its inputs.
#include "nodes/op_registry.hpp"

namespace wg {

namespace {
OpDef surfaceOp(std::string_view name, std::string_view summary, ValueType type, std::string_view symbol,
                CpuEval eval) {
  return {name, "geometry", summary, {}, ValueRule::Fixed, type, symbol, "", singleOutput(), eval, OpPurity::Varying};
}
}  // namespace

void appendGeometryOps(std::vector<OpDef>& ops) {
  ops.push_back(surfaceOp("texcoord", "mesh texture coordinate 0", ValueType::Vec2, "{@texcoord}",
                          [](const Value*, const EvalContext& c) {
                            return Value::vec2(c.surface->texcoord[0], c.surface->texcoord[1]);
                          }));
  ops.push_back(surfaceOp("texcoord1", "mesh texture coordinate 1 (the second set)", ValueType::Vec2, "{@texcoord1}",
                          [](const Value*, const EvalContext& c) {
                            return Value::vec2(c.surface->texcoord1[0], c.surface->texcoord1[1]);
                          }));
  ops.push_back(surfaceOp("world_position", "world-space position (metres)", ValueType::Vec3, "{@worldPosition}",
                          [](const Value*, const EvalContext& c) {
                            const auto& p = c.surface->worldPosition;
                            return Value::vec3(p[0], p[1], p[2]);
                          }));
  ops.back().rate = OpRate::Any;  // the vertex stage's is before its offset (snow depth)
  ops.push_back(surfaceOp("world_normal", "interpolated world-space geometric normal, unit length",
                          ValueType::Vec3, "{@worldNormal}", [](const Value*, const EvalContext& c) {
                            const auto& n = c.surface->worldNormal;
                            return Value::vec3(n[0], n[1], n[2]);
                          }));
  ops.push_back(surfaceOp("tangent", "world-space tangent; w is the bitangent sign", ValueType::Vec4,
                          "{@worldTangent}", [](const Value*, const EvalContext& c) {
                            const auto& t = c.surface->tangent;
                            return Value::vec4(t[0], t[1], t[2], t[3]);
                          }));
  ops.push_back(surfaceOp("vertex_color", "mesh vertex colour", ValueType::Vec4, "{@vertexColor}",
                          [](const Value*, const EvalContext& c) {
                            const auto& v = c.surface->vertexColor;
                            return Value::vec4(v[0], v[1], v[2], v[3]);
                          }));
  ops.push_back(surfaceOp("time", "seconds since the scene started", ValueType::Float, "{@time}",
                          [](const Value*, const EvalContext& c) { return Value::scalar(c.frame->time); }));
  ops.push_back({"parameter", "input", "reads a material parameter (set \"param\" on the node)", {},
                 ValueRule::Parameter, ValueType::Float, "{@parameter}", "", singleOutput(),
                 [](const Value*, const EvalContext& c) { return (*c.parameters)[c.parameterIndex]; },
                 OpPurity::Varying});
}

}  // namespace wg
