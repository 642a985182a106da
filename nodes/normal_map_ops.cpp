// Tangent-space normal maps: unpacking and reoriented normal mapping (RNM) blending.
#include <algorithm>
#include <cmath>

#include "nodes/op_registry.hpp"

namespace wg {

namespace {
// t.z is >= 0 for unpacked normals; the floor keeps the division finite when a
// base normal points straight down.
constexpr float kMinBaseZ = 1e-4f;
constexpr float kMinSquaredLength = 1e-12f;

Value normalized3(float x, float y, float z) {
  float s = 1.f / std::sqrt(std::max(x * x + y * y + z * z, kMinSquaredLength));
  return Value::vec3(x * s, y * s, z * s);
}

const ShaderLibrary kNormalMapLibrary = {
    "normal_map",
    R"(vec3 wg_unpack_normal(const vec3 rgb, const float strength) {
  vec3 n = rgb * 2.0 - 1.0;
  n.xy *= strength;
  return n * inversesqrt(max(dot(n, n), 1e-12));
}
vec3 wg_blend_normals_rnm(const vec3 base, const vec3 detail) {
  vec3 t = base + vec3(0.0, 0.0, 1.0);
  vec3 u = detail * vec3(-1.0, -1.0, 1.0);
  vec3 r = t * (dot(t, u) / max(t.z, 1e-4)) - u;
  return r * inversesqrt(max(dot(r, r), 1e-12));
}
)",
    {}};
}  // namespace

void appendNormalMapOps(std::vector<OpDef>& ops) {
  ops.push_back({"normal_unpack", "normal", "tangent-space normal from a [0,1] normal-map texel, xy scaled by strength",
                 {{"rgb", PortType::Vec3, std::nullopt}, {"strength", PortType::Float, Value::scalar(1.f), 0.f, 16.f}},
                 ValueRule::Fixed, ValueType::Vec3, "wg_unpack_normal({rgb}, {strength})", "", singleOutput(),
                 [](const Value* in, const EvalContext&) {
                   float s = in[1].x();
                   return normalized3((in[0].v[0] * 2.f - 1.f) * s, (in[0].v[1] * 2.f - 1.f) * s, in[0].v[2] * 2.f - 1.f);
                 },
                 OpPurity::Pure, {&kNormalMapLibrary}});
  ops.push_back({"normal_blend", "normal", "reoriented normal mapping: detail laid onto base (both tangent space)",
                 {{"base", PortType::Vec3, Value::vec3(0.f, 0.f, 1.f)}, {"detail", PortType::Vec3, std::nullopt}},
                 ValueRule::Fixed, ValueType::Vec3, "wg_blend_normals_rnm({base}, {detail})", "", singleOutput(),
                 [](const Value* in, const EvalContext&) {
                   float tx = in[0].v[0], ty = in[0].v[1], tz = in[0].v[2] + 1.f;
                   float ux = -in[1].v[0], uy = -in[1].v[1], uz = in[1].v[2];
                   float k = (tx * ux + ty * uy + tz * uz) / std::max(tz, kMinBaseZ);
                   return normalized3(tx * k - ux, ty * k - uy, tz * k - uz);
                 },
                 OpPurity::Pure, {&kNormalMapLibrary}});
}

}  // namespace wg
