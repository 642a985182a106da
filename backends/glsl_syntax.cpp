// GLSL 450 for Vulkan: blocks without instance names (members are globals, as in
// HLSL cbuffers), explicit offsets, separate texture2D and sampler objects.
#include <array>

#include "backends/shader_syntax.hpp"

namespace wg {

namespace {

// Bytes of declarations and stage frame around the body and libraries (sizes the output once).
constexpr std::size_t kFrameSizeHint = 6144;
std::size_t librarySize(const StageSource& s) {
  std::size_t n = 0;
  for (const ShaderLibrary* lib : s.libraries) n += lib->glsl.size() + 1;
  return n;
}

std::string_view glslInterfaceType(InterfaceType type) { return interfaceTypeName(type); }

void appendBlock(std::string& out, const UniformBlock& block) {
  if (block.members.empty()) return;
  out += "layout(set = " + std::to_string(block.set) + ", binding = " + std::to_string(block.binding) +
         ", std140) uniform " + block.identifier + " {\n";
  for (const auto& m : block.members)
    out += "  layout(offset = " + std::to_string(m.offset) + ") " + std::string(glslInterfaceType(m.type)) + " " +
           m.identifier + ";\n";
  out += "};\n";
}

class GlslSyntax final : public ShaderSyntax {
 public:
  ShaderLanguage language() const override { return ShaderLanguage::Glsl; }

  std::string_view typeName(ValueType type) const override {
    constexpr std::array<std::string_view, 6> kNames = {"float", "vec2", "vec3", "vec4", "bool", "texture2D"};
    return kNames[static_cast<int>(type)];
  }
  std::string splat(ValueType to, std::string_view scalar) const override {
    return std::string(typeName(to)) + "(" + std::string(scalar) + ")";
  }
  std::string_view sampleFunction(ShaderStage stage) const override {
    return stage == ShaderStage::Vertex ? "textureLod" : "texture";
  }
  std::string_view lodArgument(ShaderStage stage) const override { return stage == ShaderStage::Vertex ? ", 0.0" : ""; }

  std::string assemble(const StageSource& s) const override {
    const MaterialInterface& mi = *s.interface;
    std::string out;
    out.reserve(kFrameSizeHint + s.body.size() + librarySize(s));
    out += "#version 450\n";
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
      out += "layout(set = " + std::to_string(t.set) + ", binding = " + std::to_string(t.textureBinding) +
             ") uniform texture2D " + t.textureIdentifier + ";\n";
      out += "layout(set = " + std::to_string(t.set) + ", binding = " + std::to_string(t.samplerBinding) +
             ") uniform sampler " + t.samplerIdentifier + ";\n";
    }
    bool vertex = s.stage == ShaderStage::Vertex;
    if (vertex)
      for (const auto& a : mi.vertexInputs)
        out += "layout(location = " + std::to_string(a.location) + ") in " + std::string(glslInterfaceType(a.type)) +
               " " + a.identifier + ";\n";
    for (const auto& v : mi.varyings)
      out += "layout(location = " + std::to_string(v.location) + ") " + (vertex ? "out " : "in ") +
             std::string(glslInterfaceType(v.type)) + " " + v.identifier + ";\n";
    if (!vertex) out += "layout(location = 0) out vec4 out_color;\n";
    for (const ShaderLibrary* lib : s.libraries) {
      out += '\n';
      out += lib->glsl;
    }
    out += "\nvoid main() {\n";
    if (vertex) {
      out += "  vec3 wg_worldPosition = (frame_model * vec4(in_position, 1.0)).xyz;\n"
             "  vec3 wg_worldNormal = wg_safe_normalize((frame_normalMatrix * vec4(in_normal, 0.0)).xyz);\n"
             "  vec4 wg_worldTangent = vec4(wg_safe_normalize((frame_model * vec4(in_tangent.xyz, 0.0)).xyz), in_tangent.w);\n"
             "  vec2 wg_texcoord = in_texcoord;\n"
             "  vec4 wg_vertexColor = in_color;\n";
      if (mi.hasTexcoord1()) out += "  vec2 wg_texcoord1 = in_texcoord1;\n";
      out += s.body;
      out += "  wg_worldPosition += wg_offset;\n";
      out += "  v_worldPosition = wg_worldPosition;\n"
             "  v_worldNormal = wg_worldNormal;\n"
             "  v_worldTangent = wg_worldTangent;\n"
             "  v_texcoord = wg_texcoord;\n"
             "  v_color = wg_vertexColor;\n";
      if (mi.hasTexcoord1()) out += "  v_texcoord1 = wg_texcoord1;\n";
      out += "  gl_Position = frame_viewProjection * vec4(wg_worldPosition, 1.0);\n";
    } else {
      out += "  vec3 wg_worldPosition = v_worldPosition;\n"
             "  vec3 wg_worldNormal = wg_safe_normalize(v_worldNormal) * (gl_FrontFacing ? 1.0 : -1.0);\n"
             "  vec3 wg_tangentAxis = wg_safe_normalize(v_worldTangent.xyz - wg_worldNormal * dot(wg_worldNormal, v_worldTangent.xyz));\n"
             "  vec4 wg_worldTangent = vec4(wg_tangentAxis, v_worldTangent.w);\n"
             "  vec2 wg_texcoord = v_texcoord;\n"
             "  vec4 wg_vertexColor = v_color;\n";
      if (mi.hasTexcoord1()) out += "  vec2 wg_texcoord1 = v_texcoord1;\n";
      out += s.body;
      if (s.alphaTested) out += "  if (wg_opacity < " + formatFloat(s.alphaCutoff) + ") discard;\n";
      out += "  vec3 wg_bitangent = cross(wg_worldNormal, wg_tangentAxis) * wg_worldTangent.w;\n"
             "  vec3 wg_N = wg_safe_normalize(wg_tangentAxis * wg_normal.x + wg_bitangent * wg_normal.y + wg_worldNormal * wg_normal.z);\n"
             "  vec3 wg_V = wg_safe_normalize(frame_cameraPosition - wg_worldPosition);\n"
             "  vec3 wg_color = wg_tonemap(wg_shade(wg_baseColor, wg_metallic, wg_roughness, wg_specular, wg_occlusion, wg_emissive, wg_N, wg_V, wg_sun_shadow(wg_worldPosition, wg_worldNormal)));\n";
      out += alphaStatement(s);
      for (const auto& view : s.debugViews) {
        out += "  if (frame_debugView == " + std::to_string(view.id) + "u) ";
        if (view.alpha.empty()) out += "wg_color = " + view.expression + ";\n";
        else out += "{ wg_color = " + view.expression + "; wg_alpha = " + view.alpha + "; }\n";
      }
      out += "  out_color = vec4(wg_color, wg_alpha);\n";
    }
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
