// GLSL 4.40 for Vulkan: blocks without instance names (members are globals, as in
// HLSL cbuffers), explicit offsets, separate texture2D and sampler objects.
#include <array>

#include "backends/shader_syntax.hpp"
#include "backends/source_text.hpp"

namespace wg {

namespace {

// Bytes of declarations around the surface and the entry point (sizes the output once).
constexpr std::size_t kFrameSizeHint = 6144;

std::string_view glslInterfaceType(InterfaceType type) { return interfaceTypeName(type); }

void appendBlock(std::string& out, const UniformBlock& block) {
  if (block.members.empty()) return;
  appendText(out, "layout(set = ", Decimal{block.set}, ", binding = ", Decimal{block.binding}, ", std140) uniform ",
             block.identifier, " {\n");
  for (const auto& m : block.members)
    appendText(out, "  layout(offset = ", Decimal{m.offset}, ") ", glslInterfaceType(m.type), ' ', m.identifier, ";\n");
  out += "};\n";
}

class GlslSyntax final : public ShaderSyntax {
 public:
  ShaderLanguage language() const override { return ShaderLanguage::Glsl; }

  std::string_view typeName(ValueType type) const override {
    constexpr std::array<std::string_view, 6> kNames = {"float", "vec2", "vec3", "vec4", "bool", "texture2D"};
    return kNames[static_cast<int>(type)];
  }
  std::string stageVariable(std::string_view identifier, ShaderStage) const override { return std::string(identifier); }
  std::string splat(ValueType to, std::string_view scalar) const override {
    return std::string(typeName(to)) + "(" + std::string(scalar) + ")";
  }
  std::string_view sampleFunction(ShaderStage stage) const override {
    return stage == ShaderStage::Vertex ? "textureLod" : "texture";
  }
  std::string_view lodArgument(ShaderStage stage) const override { return stage == ShaderStage::Vertex ? ", 0.0" : ""; }

  // GLSL is the source language: everything is printed as written.
  std::string_view libraryCode(const ShaderLibrary& library) const override { return library.glsl; }
  std::string_view opCode(const OpDef& op) const override { return op.glsl; }
  std::string frameCode(std::string_view glsl, ShaderStage) const override { return std::string(glsl); }

  std::string assemble(const HostedStage& s) const override {
    const MaterialInterface& mi = *s.interface;
    std::string out;
    out.reserve(kFrameSizeHint + s.surface.size() + s.main.size());
    out += kGlslVersionLine;
    out += s.banner;
    // The frame block is the same for every material: format it once.
    static const std::string kFrameBlockText = [&] {
      std::string text;
      appendBlock(text, *mi.frame);
      return text;
    }();
    out += kFrameBlockText;
    appendBlock(out, mi.material);
    for (const auto* list : {&mi.weatherMaps, &mi.textures})
    for (const auto& t : *list) {
      appendText(out, "layout(set = ", Decimal{t.set}, ", binding = ", Decimal{t.textureBinding}, ") uniform ",
                 t.cube ? "textureCube " : "texture2D ", t.textureIdentifier, ";\n");
      appendText(out, "layout(set = ", Decimal{t.set}, ", binding = ", Decimal{t.samplerBinding}, ") uniform sampler ",
                 t.samplerIdentifier, ";\n");
    }
    bool vertex = s.stage == ShaderStage::Vertex;
    if (vertex)
      for (const auto& a : mi.vertexInputs)
        appendText(out, "layout(location = ", Decimal{a.location}, ") in ", glslInterfaceType(a.type), ' ', a.identifier,
                   ";\n");
    for (const auto& v : mi.varyings)
      appendText(out, "layout(location = ", Decimal{v.location}, ") ", vertex ? "out " : "in ", glslInterfaceType(v.type),
                 ' ', v.identifier, ";\n");
    if (!vertex) out += "layout(location = 0) out vec4 out_color;\n";
    out += s.surface;
    out += "\nvoid main() {\n";
    out += s.main;
    if (!vertex) out += "  out_color = vec4(wg_color, wg_alpha);\n";
    out += "}\n";
    return out;
  }
};

}  // namespace

const ShaderSyntax& glslSyntax() {
  static const GlslSyntax instance;
  return instance;
}

}  // namespace wg
