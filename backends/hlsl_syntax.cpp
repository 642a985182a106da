// HLSL in Shader Model 5.0 syntax for glslang's HLSL front end: cbuffers with
// packoffset (the same offsets as GLSL's std140), [[vk::binding]] plus registers,
// [[vk::location]] on stage IO, entry point "main".
#include <array>

#include "backends/shader_syntax.hpp"

namespace wg {

namespace {

// Bytes of declarations and stage frame around the body and libraries (sizes the output once).
constexpr std::size_t kFrameSizeHint = 6144;
std::size_t librarySize(const StageSource& s) {
  std::size_t n = 0;
  for (const ShaderLibrary* lib : s.libraries) n += lib->hlsl.size() + 1;
  return n;
}

std::string_view hlslInterfaceType(InterfaceType type) {
  constexpr std::array<std::string_view, 6> kNames = {"float", "float2", "float3", "float4", "uint", "float4x4"};
  return kNames[static_cast<int>(type)];
}

// packoffset names a 16-byte register and a starting component.
std::string packOffset(std::uint32_t offset) {
  constexpr std::array<char, 4> kComponents = {'x', 'y', 'z', 'w'};
  std::string out = "c" + std::to_string(offset / 16);
  std::uint32_t component = (offset % 16) / 4;
  if (component) out += std::string(".") + kComponents[component];
  return out;
}

void appendBlock(std::string& out, const UniformBlock& block) {
  if (block.members.empty()) return;
  out += "[[vk::binding(" + std::to_string(block.binding) + ", " + std::to_string(block.set) + ")]] cbuffer " +
         block.identifier + " : register(b" + std::to_string(block.binding) + ", space" + std::to_string(block.set) +
         ") {\n";
  for (const auto& m : block.members)
    out += "  " + std::string(hlslInterfaceType(m.type)) + " " + m.identifier + " : packoffset(" + packOffset(m.offset) +
           ");\n";
  out += "};\n";
}

// HLSL semantics for stage IO; locations are what Vulkan matches.
std::string semantic(std::uint32_t location) { return "TEXCOORD" + std::to_string(location); }

class HlslSyntax final : public ShaderSyntax {
 public:
  ShaderLanguage language() const override { return ShaderLanguage::Hlsl; }

  std::string_view typeName(ValueType type) const override {
    constexpr std::array<std::string_view, 6> kNames = {"float", "float2", "float3", "float4", "bool", "Texture2D"};
    return kNames[static_cast<int>(type)];
  }
  std::string splat(ValueType to, std::string_view scalar) const override {
    return "((" + std::string(typeName(to)) + ")(" + std::string(scalar) + "))";
  }
  std::string_view sampleFunction(ShaderStage stage) const override {
    return stage == ShaderStage::Vertex ? "SampleLevel" : "Sample";
  }
  std::string_view lodArgument(ShaderStage stage) const override { return stage == ShaderStage::Vertex ? ", 0.0" : ""; }

  std::string assemble(const StageSource& s) const override {
    const MaterialInterface& mi = *s.interface;
    std::string out;
    out.reserve(kFrameSizeHint + s.body.size() + librarySize(s));
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
      out += "[[vk::binding(" + std::to_string(t.textureBinding) + ", " + std::to_string(t.set) + ")]] Texture2D " +
             t.textureIdentifier + " : register(t" + std::to_string(t.textureBinding) + ", space" +
             std::to_string(t.set) + ");\n";
      out += "[[vk::binding(" + std::to_string(t.samplerBinding) + ", " + std::to_string(t.set) + ")]] SamplerState " +
             t.samplerIdentifier + " : register(s" + std::to_string(t.samplerBinding) + ", space" +
             std::to_string(t.set) + ");\n";
    }
    bool vertex = s.stage == ShaderStage::Vertex;
    if (vertex) {
      out += "struct VSInput {\n";
      for (const auto& a : mi.vertexInputs)
        out += "  [[vk::location(" + std::to_string(a.location) + ")]] " + std::string(hlslInterfaceType(a.type)) + " " +
               a.identifier + " : " + semantic(a.location) + ";\n";
      out += "};\n";
    }
    out += vertex ? "struct VSOutput {\n  float4 wg_clipPosition : SV_Position;\n" : "struct PSInput {\n";
    for (const auto& v : mi.varyings)
      out += "  [[vk::location(" + std::to_string(v.location) + ")]] " + std::string(hlslInterfaceType(v.type)) + " " +
             v.identifier + " : " + semantic(v.location) + ";\n";
    out += "};\n";
    for (const ShaderLibrary* lib : s.libraries) {
      out += '\n';
      out += lib->hlsl;
    }
    if (vertex) {
      out += "\nVSOutput main(VSInput wg_in) {\n";
      for (const auto& a : mi.vertexInputs)
        out += "  " + std::string(hlslInterfaceType(a.type)) + " " + a.identifier + " = wg_in." + a.identifier + ";\n";
      out += "  float3 wg_worldPosition = mul(frame_model, float4(in_position, 1.0)).xyz;\n"
             "  float3 wg_worldNormal = wg_safe_normalize(mul(frame_normalMatrix, float4(in_normal, 0.0)).xyz);\n"
             "  float4 wg_worldTangent = float4(wg_safe_normalize(mul(frame_model, float4(in_tangent.xyz, 0.0)).xyz), in_tangent.w);\n"
             "  float2 wg_texcoord = in_texcoord;\n"
             "  float4 wg_vertexColor = in_color;\n";
      if (mi.hasTexcoord1()) out += "  float2 wg_texcoord1 = in_texcoord1;\n";
      out += s.body;
      out += "  wg_worldPosition += wg_offset;\n";
      out += "  VSOutput wg_out;\n"
             "  wg_out.v_worldPosition = wg_worldPosition;\n"
             "  wg_out.v_worldNormal = wg_worldNormal;\n"
             "  wg_out.v_worldTangent = wg_worldTangent;\n"
             "  wg_out.v_texcoord = wg_texcoord;\n"
             "  wg_out.v_color = wg_vertexColor;\n";
      if (mi.hasTexcoord1()) out += "  wg_out.v_texcoord1 = wg_texcoord1;\n";
      out += "  wg_out.wg_clipPosition = mul(frame_viewProjection, float4(wg_worldPosition, 1.0));\n"
             "  return wg_out;\n";
    } else {
      out += "\nfloat4 main(PSInput wg_in, bool wg_frontFacing : SV_IsFrontFace) : SV_Target0 {\n";
      out += "  float3 wg_worldPosition = wg_in.v_worldPosition;\n"
             "  float3 wg_worldNormal = wg_safe_normalize(wg_in.v_worldNormal) * (wg_frontFacing ? 1.0 : -1.0);\n"
             "  float3 wg_tangentAxis = wg_safe_normalize(wg_in.v_worldTangent.xyz - wg_worldNormal * dot(wg_worldNormal, wg_in.v_worldTangent.xyz));\n"
             "  float4 wg_worldTangent = float4(wg_tangentAxis, wg_in.v_worldTangent.w);\n"
             "  float2 wg_texcoord = wg_in.v_texcoord;\n"
             "  float4 wg_vertexColor = wg_in.v_color;\n";
      if (mi.hasTexcoord1()) out += "  float2 wg_texcoord1 = wg_in.v_texcoord1;\n";
      out += s.body;
      if (s.alphaTested) out += "  if (wg_opacity < " + formatFloat(s.alphaCutoff) + ") discard;\n";
      out += "  float3 wg_bitangent = cross(wg_worldNormal, wg_tangentAxis) * wg_worldTangent.w;\n"
             "  float3 wg_N = wg_safe_normalize(wg_tangentAxis * wg_normal.x + wg_bitangent * wg_normal.y + wg_worldNormal * wg_normal.z);\n"
             "  float3 wg_V = wg_safe_normalize(frame_cameraPosition - wg_worldPosition);\n"
             "  float3 wg_color = wg_tonemap(wg_shade(wg_baseColor, wg_metallic, wg_roughness, wg_specular, wg_occlusion, wg_emissive, wg_N, wg_V, wg_sun_shadow(wg_worldPosition, wg_worldNormal)));\n";
      out += alphaStatement(s);
      for (const auto& view : s.debugViews) {
        out += "  if (frame_debugView == " + std::to_string(view.id) + "u) ";
        if (view.alpha.empty()) out += "wg_color = " + view.expression + ";\n";
        else out += "{ wg_color = " + view.expression + "; wg_alpha = " + view.alpha + "; }\n";
      }
      out += "  return float4(wg_color, wg_alpha);\n";
    }
    out += "}\n";
    return out;
  }
};

}  // namespace

const ShaderSyntax& hlslSyntax() {
  static const HlslSyntax instance;
  return instance;
}

}  // namespace wg
