// Texture sampling. Wrap and filter belong to the texture's declaration (they become
// its sampler); the vertex stage samples mip 0 explicitly ({@sampleFn}/{@lodArg}).
#include "nodes/op_registry.hpp"
#include "nodes/texture_sampling.hpp"

namespace wg {

void appendTextureOps(std::vector<OpDef>& ops) {
  ops.push_back({"sample", "texture", "samples a declared texture at uv",
                 {{"texture", PortType::TextureName, std::nullopt}, {"uv", PortType::Vec2, std::nullopt}},
                 ValueRule::Fixed, ValueType::Vec4,
                 "{@sampleFn}(sampler2D({@texture}, {@sampler}), {uv}{@lodArg})", "",
                 {{"rgba", ""}, {"rgb", ".rgb"}, {"r", ".r"}, {"g", ".g"}, {"b", ".b"}, {"a", ".a"}},
                 [](const Value* in, const EvalContext& c) {
                   if (!c.textures) return Value::vec4(0.f, 0.f, 0.f, 1.f);
                   return c.textures->sample(static_cast<int>(in[0].x()), in[1].v[0], in[1].v[1]);
                 },
                 OpPurity::Varying});
}

}  // namespace wg
