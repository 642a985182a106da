#include "compiler/content_hash.hpp"

#include <bit>

namespace wg {

void StableHasher::add(std::string_view bytes) {
  for (unsigned char c : bytes) {
    state_ ^= c;
    state_ *= kPrime;
  }
  add(static_cast<std::uint64_t>(bytes.size()));  // length-prefix free: separates fields
}

std::string StableHasher::hex() const {
  static const char* digits = "0123456789abcdef";
  std::string out(16, '0');
  for (int i = 0; i < 16; ++i) out[15 - i] = digits[(state_ >> (4 * i)) & 15];
  return out;
}

namespace {
void addValue(StableHasher& h, const Value& v) {
  h.add(static_cast<std::uint64_t>(v.type));
  for (int i = 0; i < v.width(); ++i) h.add(std::bit_cast<std::uint32_t>(v.v[i]));
}
// One wrap and filter for both axes and directions, linear: the settings every
// texture had before per-axis wrap, min/mag filters and colour spaces, hashed as then.
void addSampler(StableHasher& h, const SamplerState& s) {
  h.add(static_cast<std::uint64_t>(s.wrapU) * 16 + static_cast<std::uint64_t>(s.magFilter));
  if (s.wrapV == s.wrapU && s.minFilter == s.magFilter && s.colorSpace == ColorSpace::Linear) return;
  h.add("sampler");
  h.add(static_cast<std::uint64_t>(s.wrapV) * 256 + static_cast<std::uint64_t>(s.minFilter) * 16 +
        static_cast<std::uint64_t>(s.colorSpace));
}
void addOperand(StableHasher& h, const Operand& o) {
  h.add(static_cast<std::uint64_t>(o.kind));
  if (o.kind == Operand::Kind::Node) {
    h.add(o.node);
    h.add(o.output);
  } else if (o.kind == Operand::Kind::Texture) {
    h.add(static_cast<std::uint64_t>(o.texture));
  } else {
    addValue(h, o.constant);
  }
}
}  // namespace

std::string contentHash(const IrGraph& graph) {
  StableHasher h;
  h.add(graph.name);
  for (const auto& node : graph.nodes) {
    h.add(node.op->name);
    h.add(node.text);
    h.add(static_cast<std::uint64_t>(node.parameter + 1));
    h.add(static_cast<std::uint64_t>(node.valueType));
    for (const auto& o : node.inputs) addOperand(h, o);
  }
  graph.forEachRoot([&](const Operand& o) { addOperand(h, o); });
  for (const auto& p : graph.parameters) {
    h.add(p.name);
    h.add(p.label);
    addValue(h, p.defaultValue);
    h.add(p.min ? std::bit_cast<std::uint32_t>(*p.min) : 0xFFFFFFFFull << 32);
    h.add(p.max ? std::bit_cast<std::uint32_t>(*p.max) : 0xFFFFFFFFull << 32);
  }
  for (const auto& t : graph.textures) {
    h.add(t.name);
    h.add(t.file);
    h.add(t.generator);
    h.add(t.seed);
    h.add(static_cast<std::uint64_t>(t.size));
    h.add(t.options.dump());
    addSampler(h, t.sampler);
  }
  h.add(static_cast<std::uint64_t>(graph.alphaTested()));
  h.add(std::bit_cast<std::uint32_t>(graph.alphaCutoff));
  h.add(graph.weather.preset);
  // Later fields are hashed only when set, so graphs without them keep their hashes.
  if (graph.alphaMode == AlphaMode::Blend) h.add(alphaModeName(graph.alphaMode));
  if (graph.doubleSided) h.add("doubleSided");
  if (graph.weather.steep) {
    h.add(graph.weather.steep->preset);
    h.add(std::bit_cast<std::uint32_t>(graph.weather.steep->fromDegrees));
    h.add(std::bit_cast<std::uint32_t>(graph.weather.steep->toDegrees));
  }
  // Effects switched away from the preset's: the reflection lists them even where the
  // shaders come out the same (relief on a preset without snow or ice). Without weather
  // it lists none.
  if (auto preset = weatherPreset(graph.weather.preset); preset && graph.weather.active())
    for (const auto& f : weatherEffectFlags())
      if (graph.weather.effects.*(f.flag) != preset->effects.*(f.flag)) {
        h.add(f.name);
        h.add(static_cast<std::uint64_t>(graph.weather.effects.*(f.flag)));
      }
  return h.hex();
}

}  // namespace wg
