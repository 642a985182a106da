// HLSL in Shader Model 5.0 syntax for glslang's HLSL front end: cbuffers with
// packoffset (the same offsets as GLSL's std140), [[vk::binding]] plus registers,
// [[vk::location]] on stage IO, entry point "main".
#include <array>
#include <map>
#include <mutex>

#include "backends/derived_hlsl.hpp"
#include "backends/shader_syntax.hpp"
#include "backends/source_text.hpp"

namespace wg {

namespace {

// Bytes of declarations around the surface and the entry point (sizes the output once).
constexpr std::size_t kFrameSizeHint = 6144;

std::string_view hlslInterfaceType(InterfaceType type) {
  constexpr std::array<std::string_view, 6> kNames = {"float", "float2", "float3", "float4", "uint", "float4x4"};
  return kNames[static_cast<int>(type)];
}

// packoffset names a 16-byte register and a starting component.
void appendPackOffset(std::string& out, std::uint32_t offset) {
  constexpr std::array<char, 4> kComponents = {'x', 'y', 'z', 'w'};
  appendText(out, 'c', Decimal{offset / 16});
  if (std::uint32_t component = (offset % 16) / 4) appendText(out, '.', kComponents[component]);
}

void appendBlock(std::string& out, const UniformBlock& block) {
  if (block.members.empty()) return;
  appendText(out, "[[vk::binding(", Decimal{block.binding}, ", ", Decimal{block.set}, ")]] cbuffer ", block.identifier,
             " : register(b", Decimal{block.binding}, ", space", Decimal{block.set}, ") {\n");
  for (const auto& m : block.members) {
    appendText(out, "  ", hlslInterfaceType(m.type), ' ', m.identifier, " : packoffset(");
    appendPackOffset(out, m.offset);
    out += ");\n";
  }
  out += "};\n";
}

// HLSL semantics for stage IO (TEXCOORD<location>); locations are what Vulkan matches.
void appendStageVariable(std::string& out, const StageVariable& v) {
  appendText(out, "  [[vk::location(", Decimal{v.location}, ")]] ", hlslInterfaceType(v.type), ' ', v.identifier,
             " : TEXCOORD", Decimal{v.location}, ";\n");
}

// A varying in the entry point's struct: the vertex stage's output, the fragment's input.
std::string stageStructMember(std::string_view identifier, ShaderStage stage) {
  return (stage == ShaderStage::Vertex ? "wg_out." : "wg_in.") + std::string(identifier);
}

// Stage IO lives in the entry point's structs, where the frame's GLSL (stage_frame.cpp)
// names the varyings, gl_Position and gl_FrontFacing as globals.
HlslTranslation stageIoTranslation(ShaderStage stage) {
  static constexpr std::array<std::string_view, 6> kVaryings = {"v_worldPosition", "v_worldNormal", "v_worldTangent",
                                                                "v_texcoord",      "v_color",       "v_texcoord1"};
  // The renames are views, so the spelled members live as long as the program.
  static const auto kMembers = [] {
    std::array<std::array<std::string, kVaryings.size()>, 2> members;
    for (std::size_t i = 0; i < kVaryings.size(); ++i) {
      members[0][i] = stageStructMember(kVaryings[i], ShaderStage::Vertex);
      members[1][i] = stageStructMember(kVaryings[i], ShaderStage::Fragment);
    }
    return members;
  }();
  bool vertex = stage == ShaderStage::Vertex;
  HlslTranslation translation = frameMatrixTranslation();
  for (std::size_t i = 0; i < kVaryings.size(); ++i) translation.renames.emplace_back(kVaryings[i], kMembers[vertex ? 0 : 1][i]);
  if (vertex) translation.renames.emplace_back("gl_Position", "wg_out.wg_clipPosition");
  else translation.renames.emplace_back("gl_FrontFacing", "wg_frontFacing");
  return translation;
}

class HlslSyntax final : public ShaderSyntax {
 public:
  ShaderLanguage language() const override { return ShaderLanguage::Hlsl; }

  std::string_view typeName(ValueType type) const override {
    constexpr std::array<std::string_view, 6> kNames = {"float", "float2", "float3", "float4", "bool", "Texture2D"};
    return kNames[static_cast<int>(type)];
  }
  std::string stageVariable(std::string_view identifier, ShaderStage stage) const override {
    return stageStructMember(identifier, stage);
  }
  std::string splat(ValueType to, std::string_view scalar) const override {
    return "((" + std::string(typeName(to)) + ")(" + std::string(scalar) + "))";
  }
  std::string_view sampleFunction(ShaderStage stage) const override {
    return stage == ShaderStage::Vertex ? "SampleLevel" : "Sample";
  }
  std::string_view lodArgument(ShaderStage stage) const override { return stage == ShaderStage::Vertex ? ", 0.0" : ""; }

  std::string_view libraryCode(const ShaderLibrary& library) const override { return derivedHlsl(library); }
  std::string_view opCode(const OpDef& op) const override { return derivedHlsl(op); }
  // The frame's GLSL comes in a handful of fixed texts (stage_frame.cpp), so each is
  // translated once and then looked up: the translation was 4 % of a compile.
  std::string frameCode(std::string_view glsl, ShaderStage stage) const override {
    static const HlslTranslation kVertex = stageIoTranslation(ShaderStage::Vertex);
    static const HlslTranslation kFragment = stageIoTranslation(ShaderStage::Fragment);
    static std::mutex mutex;
    static std::array<std::map<std::string, std::string, std::less<>>, 2> translated;  // by stage
    bool vertex = stage == ShaderStage::Vertex;
    auto& byText = translated[vertex ? 0 : 1];
    std::lock_guard lock(mutex);
    auto it = byText.find(glsl);
    if (it == byText.end()) it = byText.emplace(std::string(glsl), glslToHlsl(glsl, vertex ? kVertex : kFragment)).first;
    return it->second;
  }

  std::string assemble(const HostedStage& s) const override {
    const MaterialInterface& mi = *s.interface;
    std::string out;
    out.reserve(kFrameSizeHint + s.surface.size() + s.main.size());
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
      appendText(out, "[[vk::binding(", Decimal{t.textureBinding}, ", ", Decimal{t.set}, ")]] ",
                 t.cube ? "TextureCube " : "Texture2D ", t.textureIdentifier, " : register(t", Decimal{t.textureBinding}, ", space", Decimal{t.set}, ");\n");
      appendText(out, "[[vk::binding(", Decimal{t.samplerBinding}, ", ", Decimal{t.set}, ")]] SamplerState ",
                 t.samplerIdentifier, " : register(s", Decimal{t.samplerBinding}, ", space", Decimal{t.set}, ");\n");
    }
    bool vertex = s.stage == ShaderStage::Vertex;
    if (vertex) {
      out += "struct VSInput {\n";
      for (const auto& a : mi.vertexInputs) appendStageVariable(out, a);
      out += "};\n";
    }
    out += vertex ? "struct VSOutput {\n  float4 wg_clipPosition : SV_Position;\n" : "struct PSInput {\n";
    for (const auto& v : mi.varyings) appendStageVariable(out, v);
    out += "};\n";
    out += s.surface;
    if (vertex) {
      out += "\nVSOutput main(VSInput wg_in) {\n";
      for (const auto& a : mi.vertexInputs)
        appendText(out, "  ", hlslInterfaceType(a.type), ' ', a.identifier, " = wg_in.", a.identifier, ";\n");
      out += "  VSOutput wg_out;\n";
      out += s.main;
      out += "  return wg_out;\n";
    } else {
      out += "\nfloat4 main(PSInput wg_in, bool wg_frontFacing : SV_IsFrontFace) : SV_Target0 {\n";
      out += s.main;
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
