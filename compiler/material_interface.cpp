#include "compiler/material_interface.hpp"

#include <algorithm>
#include <array>

#include "compiler/identifier.hpp"
#include "nodes/weather_maps.hpp"

namespace wg {

std::string_view interfaceTypeName(InterfaceType type) {
  constexpr std::array<std::string_view, 6> kNames = {"float", "vec2", "vec3", "vec4", "uint", "mat4"};
  return kNames[static_cast<int>(type)];
}

InterfaceType interfaceTypeOf(ValueType type) {
  switch (type) {
    case ValueType::Vec2: return InterfaceType::Vec2;
    case ValueType::Vec3: return InterfaceType::Vec3;
    case ValueType::Vec4: return InterfaceType::Vec4;
    case ValueType::Bool: return InterfaceType::Uint;  // SPIR-V has no bool in uniform blocks
    default: return InterfaceType::Float;
  }
}

namespace {
// std140 base alignment and size in bytes (GLSL 4.50 spec, section 7.6.2.2).
std::pair<std::uint32_t, std::uint32_t> std140AlignAndSize(InterfaceType type) {
  switch (type) {
    case InterfaceType::Float:
    case InterfaceType::Uint: return {4, 4};
    case InterfaceType::Vec2: return {8, 8};
    case InterfaceType::Vec3: return {16, 12};
    case InterfaceType::Vec4: return {16, 16};
    case InterfaceType::Mat4: return {16, 64};
  }
  return {4, 4};
}
constexpr std::uint32_t kStd140BlockAlignment = 16;

bool usesOp(const IrGraph& graph, std::string_view op) {
  return std::any_of(graph.nodes.begin(), graph.nodes.end(), [&](const IrNode& n) { return n.op->name == op; });
}
}  // namespace

void layoutStd140(UniformBlock& block) {
  std::uint32_t offset = 0;
  for (auto& member : block.members) {
    auto [align, size] = std140AlignAndSize(member.type);
    offset = (offset + align - 1) / align * align;
    member.offset = offset;
    member.size = size;
    offset += size;
  }
  block.size = (offset + kStd140BlockAlignment - 1) / kStd140BlockAlignment * kStd140BlockAlignment;
}

bool MaterialInterface::hasTexcoord1() const {
  return std::any_of(vertexInputs.begin(), vertexInputs.end(), [](const StageVariable& v) { return v.name == "texcoord1"; });
}

MaterialInterface buildMaterialInterface(const IrGraph& graph) {
  MaterialInterface mi;
  mi.frame = &frameBlock();
  // Names made from the user's: their prefixes (mat_, tex_, smp_) keep them apart from
  // every fixed global (frame_, wg_, in_, v_, the blocks), so only they need a scope.
  IdentifierScope userNames;

  mi.material.name = "Material";
  mi.material.identifier = "MaterialBlock";
  mi.material.set = 1;
  mi.material.binding = 0;
  // Parameters are sorted by name, so identifiers and offsets are deterministic.
  for (std::size_t i = 0; i < graph.parameters.size(); ++i) {
    const auto& p = graph.parameters[i];
    mi.material.members.push_back(
        {p.name, userNames.make("mat_" + p.name), interfaceTypeOf(p.type), 0, 0, static_cast<int>(i)});
  }
  layoutStd140(mi.material);

  std::uint32_t binding = 1;  // binding 0 of set 1 is the material block
  for (std::size_t i = 0; i < graph.textures.size(); ++i) {
    const auto& t = graph.textures[i];
    TextureBinding b;
    b.texture = static_cast<int>(i);
    b.name = t.name;
    b.textureIdentifier = userNames.make("tex_" + t.name);
    b.samplerIdentifier = userNames.make("smp_" + t.name);
    b.textureBinding = binding++;
    b.samplerBinding = binding++;
    mi.textures.push_back(std::move(b));
  }

  // Shared weather maps: set 0 next to the frame block, at the table's fixed bindings.
  // The host's own maps (its lighting's) are in every full stage.
  for (const WeatherMap& map : weatherMaps()) {
    bool used = !map.surface || std::any_of(graph.nodes.begin(), graph.nodes.end(), [&](const IrNode& n) {
      return std::find(n.op->weatherMaps.begin(), n.op->weatherMaps.end(), map.name) != n.op->weatherMaps.end();
    });
    if (used)
      mi.weatherMaps.push_back({-1, std::string(map.name), std::string(map.texture), std::string(map.sampler), 0,
                                map.binding, map.binding + 1, map.cube});
  }

  const std::array<std::pair<std::string_view, InterfaceType>, 5> kAttributes = {{
      {"position", InterfaceType::Vec3},
      {"normal", InterfaceType::Vec3},
      {"tangent", InterfaceType::Vec4},
      {"texcoord", InterfaceType::Vec2},
      {"color", InterfaceType::Vec4},
  }};
  for (std::uint32_t i = 0; i < kAttributes.size(); ++i) {
    auto [name, type] = kAttributes[i];
    mi.vertexInputs.push_back({std::string(name), "in_" + std::string(name), type, i});
  }
  const std::array<std::pair<std::string_view, InterfaceType>, 5> kVaryings = {{
      {"worldPosition", InterfaceType::Vec3},
      {"worldNormal", InterfaceType::Vec3},
      {"worldTangent", InterfaceType::Vec4},
      {"texcoord", InterfaceType::Vec2},
      {"color", InterfaceType::Vec4},
  }};
  for (std::uint32_t i = 0; i < kVaryings.size(); ++i) {
    auto [name, type] = kVaryings[i];
    mi.varyings.push_back({std::string(name), "v_" + std::string(name), type, i});
  }
  // The second texture coordinate set only when a node reads it, so other materials
  // keep their vertex format.
  if (usesOp(graph, "texcoord1")) {
    mi.vertexInputs.push_back({"texcoord1", "in_texcoord1", InterfaceType::Vec2, static_cast<std::uint32_t>(kAttributes.size())});
    mi.varyings.push_back({"texcoord1", "v_texcoord1", InterfaceType::Vec2, static_cast<std::uint32_t>(kVaryings.size())});
  }
  // The vertex-rate pass's values, named by their order alone.
  for (std::size_t k = 0; k < graph.interpolants.size(); ++k) {
    std::string name = "interpolant" + std::to_string(k);
    mi.interpolantVaryings.push_back(mi.varyings.size());
    mi.varyings.push_back({name, "v_" + name, interfaceTypeOf(graph.nodes[graph.interpolants[k]].valueType),
                           static_cast<std::uint32_t>(mi.varyings.size())});
  }
  return mi;
}

}  // namespace wg
