// Procedural ops: the seed's Panner(h, v, time) and deterministic lattice noise.
#include "nodes/lattice_noise.hpp"
#include "nodes/op_registry.hpp"

namespace wg {

void appendProceduralOps(std::vector<OpDef>& ops) {
  // Seed 000, section 3.2.3: Panner(h, v, time) pans uv h units horizontally and v
  // units vertically per second.
  ops.push_back({"panner", "procedural", "uv + speed * time (seed 000, Panner(h, v, time))",
                 {{"uv", PortType::Vec2, std::nullopt}, {"speed", PortType::Vec2, Value::vec2(0.f, 0.f)}},
                 ValueRule::Fixed, ValueType::Vec2, "({uv} + {speed} * {@time})", "", singleOutput(),
                 [](const Value* in, const EvalContext& c) {
                   float t = c.frame->time;
                   return Value::vec2(in[0].v[0] + in[1].v[0] * t, in[0].v[1] + in[1].v[1] * t);
                 },
                 OpPurity::Varying});
  ops.push_back({"value_noise", "procedural", "smooth value noise of p * scale, in [0, 1]",
                 {{"p", PortType::Vec2, std::nullopt}, {"scale", PortType::Float, Value::scalar(1.f)}},
                 ValueRule::Fixed, ValueType::Float, "wg_value_noise({p} * {scale})", "", singleOutput(),
                 [](const Value* in, const EvalContext&) {
                   float s = in[1].x();
                   return Value::scalar(valueNoise(in[0].v[0] * s, in[0].v[1] * s));
                 },
                 OpPurity::Pure, {&kLatticeNoiseLibrary}});
  ops.push_back({"gradient_noise", "procedural", "gradient (Perlin-style) noise of p * scale, in [0, 1]",
                 {{"p", PortType::Vec2, std::nullopt}, {"scale", PortType::Float, Value::scalar(1.f)}},
                 ValueRule::Fixed, ValueType::Float, "wg_gradient_noise({p} * {scale})", "", singleOutput(),
                 [](const Value* in, const EvalContext&) {
                   float s = in[1].x();
                   return Value::scalar(gradientNoise(in[0].v[0] * s, in[0].v[1] * s));
                 },
                 OpPurity::Pure, {&kLatticeNoiseLibrary}});
}

}  // namespace wg
