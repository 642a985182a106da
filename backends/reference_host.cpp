#include "backends/reference_host.hpp"

#include <array>
#include <stdexcept>

#include "backends/library_functions.hpp"
#include "backends/shader_syntax.hpp"
#include "backends/source_text.hpp"
#include "backends/surface_writer.hpp"

namespace wg {

namespace {

// Each vertex input of the surface from the host's attributes and frame block. The
// host owns the object transform; the surface normalises the normal and tangent.
constexpr std::array<std::pair<std::string_view, std::string_view>, 7> kVertexInputs = {{
    {"worldPosition", "(frame_model * vec4(in_position, 1.0)).xyz"},
    {"worldNormal", "(frame_normalMatrix * vec4(in_normal, 0.0)).xyz"},
    {"worldTangent", "vec4((frame_model * vec4(in_tangent.xyz, 0.0)).xyz, in_tangent.w)"},
    {"texcoord", "in_texcoord"},
    {"color", "in_color"},
    {"texcoord1", "in_texcoord1"},
    {"cameraPosition", "frame_cameraPosition"},
}};

std::string_view vertexInputExpression(std::string_view field) {
  for (const auto& [name, expression] : kVertexInputs)
    if (name == field) return expression;
  throw std::logic_error("the reference host has no value for the surface's vertex input " + std::string(field));
}

constexpr std::string_view kClipPosition =
    "  gl_Position = frame_viewProjection * vec4(wg_vertexOutput.worldPosition, 1.0);\n";
constexpr std::string_view kFragmentEnvironment =
    "  wg_fragmentInput.frontFacing = gl_FrontFacing;\n"
    "  wg_fragmentInput.cameraPosition = frame_cameraPosition;\n";
// The host's geometry for its lighting and debug views, then eq. 2.1-2.5 with the sun's
// shadow and the sky (wg_shade), tone mapped.
constexpr std::string_view kFragmentLighting =
    "  vec3 wg_worldPosition = v_worldPosition;\n"
    "  vec3 wg_worldNormal = wg_safe_normalize(v_worldNormal) * (gl_FrontFacing ? 1.0 : -1.0);\n"
    "  vec4 wg_worldTangent = vec4(wg_safe_normalize(v_worldTangent.xyz - wg_worldNormal * dot(wg_worldNormal, "
    "v_worldTangent.xyz)), v_worldTangent.w);\n"
    "  vec2 wg_texcoord = v_texcoord;\n"
    "  vec3 wg_V = wg_safe_normalize(frame_cameraPosition - wg_worldPosition);\n"
    "  vec3 wg_color = wg_tonemap(wg_shade(wg_surface.baseColor, wg_surface.metallic, wg_surface.roughness, "
    "wg_surface.specular, wg_surface.occlusion, wg_surface.emissive, wg_surface.normal, wg_V, "
    "wg_sun_shadow(wg_worldPosition, wg_worldNormal)));\n";

// The library functions the host's own statements call, for the embedded surface to
// emit with its own.
const std::vector<std::string_view>& hostCalls(ShaderStage stage) {
  static const auto kCalls = [] {
    std::array<std::vector<std::string_view>, 2> calls;
    forEachLibraryCall(kFragmentLighting, [&](std::string_view name) { calls[1].push_back(name); });
    return calls;
  }();
  return kCalls[stage == ShaderStage::Vertex ? 0 : 1];
}

class ReferenceHost {
 public:
  ReferenceHost(const IrGraph& graph, const SurfaceInterface& surface, const ShaderSyntax& syntax, ShaderStage stage)
      : graph_(graph), s_(surface), syntax_(syntax), stage_(stage) {}

  std::string main() const { return stage_ == ShaderStage::Vertex ? vertexMain() : fragmentMain(); }

 private:
  const MaterialInterface& mi() const { return s_.prefixed; }

  // The surface's input from the attributes; its output to the varyings and the clip position.
  std::string vertexMain() const {
    std::string glsl;
    appendText(glsl, "  ", s_.vertexInput.name, " wg_vertexInput;\n");
    for (const auto& f : s_.vertexInput.fields)
      appendText(glsl, "  wg_vertexInput.", f.name, " = ", vertexInputExpression(f.name), ";\n");
    appendText(glsl, "  ", s_.vertexOutput.name, " wg_vertexOutput = ", s_.vertexFunction, "(wg_vertexInput);\n");
    std::string out = syntax_.frameCode(glsl, stage_);
    for (const auto& v : mi().varyings)
      appendText(out, "  ", syntax_.stageVariable(v.identifier, stage_), " = wg_vertexOutput.", v.name, ";\n");
    out += syntax_.frameCode(kClipPosition, stage_);
    return out;
  }

  // The surface's input from the varyings, the alpha test on its opacity, the lighting,
  // the alpha and the debug views.
  std::string fragmentMain() const {
    std::string out;
    appendText(out, "  ", s_.fragmentInput.name, " wg_fragmentInput;\n");
    for (const auto& v : mi().varyings)
      appendText(out, "  wg_fragmentInput.", v.name, " = ", syntax_.stageVariable(v.identifier, stage_), ";\n");
    out += syntax_.frameCode(kFragmentEnvironment, stage_);
    appendText(out, "  ", s_.fragmentOutput.name, " wg_surface = ", s_.fragmentFunction, "(wg_fragmentInput);\n");
    if (graph_.alphaTested()) appendText(out, "  if (wg_surface.opacity < ", formatFloat(graph_.alphaCutoff), ") discard;\n");
    out += syntax_.frameCode(kFragmentLighting, stage_);
    // A blended material's lit colour carries its opacity; AOVs keep 1, so read-backs
    // still tell surface from background.
    out += graph_.alphaMode == AlphaMode::Blend ? "  float wg_alpha = frame_debugView == 0u ? wg_surface.opacity : 1.0;\n"
                                                : "  float wg_alpha = 1.0;\n";
    appendDebugViews(out);
    return out;
  }

  // One switch, not a compare and branch per view: about 90 fewer instructions in a
  // fragment module for glslang and the validator, and about 50 fewer after spirv-opt.
  // View 0 ("lit") has no case.
  void appendDebugViews(std::string& out) const {
    if (graph_.debugViews.empty()) return;
    out += "  switch (frame_debugView) {\n";
    for (const auto& view : graph_.debugViews) {
      appendText(out, "    case ", Decimal{view.id}, "u: wg_color = ", debugColor(view), "; ");
      if (view.source == DebugSource::Tangent) out += "wg_alpha = wg_worldTangent.w; ";
      out += "break;\n";
    }
    out += "  }\n";
  }

  std::string debugColor(const IrDebugView& view) const {
    switch (view.source) {
      case DebugSource::Slot: {
        std::string field = "wg_surface." + std::string(surfaceOutputField(view.slot));
        bool scalar = view.slot >= kPbrFieldCount || pbrFields()[view.slot].type == ValueType::Float;
        return scalar ? syntax_.splat(ValueType::Vec3, field) : field;
      }
      case DebugSource::ShadingNormal: return "(wg_surface.normal * 0.5 + 0.5)";
      case DebugSource::WorldPosition: return "wg_worldPosition";
      case DebugSource::GeometricNormal: return "wg_worldNormal";
      case DebugSource::Texcoord: return std::string(syntax_.typeName(ValueType::Vec3)) + "(wg_texcoord, 0.0)";
      case DebugSource::Tangent: return "wg_worldTangent.xyz";
    }
    throw std::logic_error("unhandled debug source");
  }

  const IrGraph& graph_;
  const SurfaceInterface& s_;
  const ShaderSyntax& syntax_;
  ShaderStage stage_;
};

}  // namespace

std::string writeReferenceHostStage(const IrGraph& graph, const SurfaceInterface& surface, ShaderLanguage language,
                                    ShaderStage stage, std::string_view contentHash,
                                    const std::vector<std::string>& nodeNames) {
  const ShaderSyntax& syntax = syntaxFor(language);
  HostedStage hosted;
  hosted.stage = stage;
  hosted.interface = &surface.prefixed;
  hosted.banner =
      std::string(kStageBannerPrefix) + WEATHERGEN_VERSION " from material " + std::string(contentHash) + ". Do not edit.\n";
  hosted.surface = writeEmbeddedSurfaceStage(graph, surface, language, stage, nodeNames, hostCalls(stage));
  hosted.main = ReferenceHost(graph, surface, syntax, stage).main();
  return syntax.assemble(hosted);
}

}  // namespace wg
