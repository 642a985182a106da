#include "backends/stage_frame.hpp"

#include "backends/library_functions.hpp"
#include "backends/source_text.hpp"

namespace wg {

namespace {
constexpr std::string_view kVertexEpilogue =
    "  wg_worldPosition += wg_offset;\n"
    "  v_worldPosition = wg_worldPosition;\n"
    "  v_worldNormal = wg_worldNormal;\n"
    "  v_worldTangent = wg_worldTangent;\n"
    "  v_texcoord = wg_texcoord;\n"
    "  v_color = wg_vertexColor;\n";
constexpr std::string_view kFragmentPrologue =
    "  vec3 wg_worldPosition = v_worldPosition;\n"
    "  vec3 wg_worldNormal = wg_safe_normalize(v_worldNormal) * (gl_FrontFacing ? 1.0 : -1.0);\n"
    "  vec3 wg_tangentAxis = wg_safe_normalize(v_worldTangent.xyz - wg_worldNormal * dot(wg_worldNormal, v_worldTangent.xyz));\n"
    "  vec4 wg_worldTangent = vec4(wg_tangentAxis, v_worldTangent.w);\n"
    // Before the weather, written as its tangent frames write it, so spirv-opt shares one.
    "  vec3 wg_bitangent = cross(wg_worldNormal, wg_worldTangent.xyz) * wg_worldTangent.w;\n"
    "  vec2 wg_texcoord = v_texcoord;\n"
    "  vec4 wg_vertexColor = v_color;\n";
// The shading normal: the material's tangent-space normal in world space.
constexpr std::string_view kShadingNormal =
    "  vec3 wg_N = wg_safe_normalize(wg_tangentAxis * wg_normal.x + wg_bitangent * wg_normal.y + wg_worldNormal * wg_normal.z);\n";
// A surface's vertex function takes world-space geometry from the host (which owns the
// object transform, skinning and instancing) in its input struct, wg_in.
constexpr std::string_view kSurfaceVertexPrologue =
    "  vec3 wg_worldPosition = wg_in.worldPosition;\n"
    "  vec3 wg_worldNormal = wg_safe_normalize(wg_in.worldNormal);\n"
    "  vec4 wg_worldTangent = vec4(wg_safe_normalize(wg_in.worldTangent.xyz), wg_in.worldTangent.w);\n"
    "  vec2 wg_texcoord = wg_in.texcoord;\n"
    "  vec4 wg_vertexColor = wg_in.color;\n";
// Both surface functions read the eye from their input (snow's distance fade, glitter).
constexpr std::string_view kSurfaceCamera = "  vec3 wg_cameraPosition = wg_in.cameraPosition;\n";

std::vector<std::string_view> callsIn(std::initializer_list<std::string_view> texts) {
  std::vector<std::string_view> calls;
  for (std::string_view text : texts) forEachLibraryCall(text, [&](std::string_view name) { calls.push_back(name); });
  return calls;
}
}  // namespace

const std::vector<std::string_view>& surfaceFrameLibraryCalls(ShaderStage stage) {
  static const std::vector<std::string_view> kVertex = callsIn({kSurfaceVertexPrologue, kVertexEpilogue});
  static const std::vector<std::string_view> kFragment = callsIn({kFragmentPrologue, kShadingNormal});
  return stage == ShaderStage::Vertex ? kVertex : kFragment;
}

SurfaceFrameCode surfaceFrameCode(const StageSource& s, const ShaderSyntax& syntax) {
  bool texcoord1 = s.interface->hasTexcoord1();
  if (s.stage == ShaderStage::Vertex) {
    std::string prologue(kSurfaceVertexPrologue);
    prologue += kSurfaceCamera;
    if (texcoord1) prologue += "  vec2 wg_texcoord1 = wg_in.texcoord1;\n";
    std::string epilogue(kVertexEpilogue);
    if (texcoord1) epilogue += "  v_texcoord1 = wg_texcoord1;\n";
    return {syntax.frameCode(prologue, s.stage), syntax.frameCode(epilogue, s.stage)};
  }
  std::string prologue(kFragmentPrologue);
  if (texcoord1) prologue += "  vec2 wg_texcoord1 = v_texcoord1;\n";
  prologue += kSurfaceCamera;
  return {syntax.frameCode(prologue, s.stage), syntax.frameCode(kShadingNormal, s.stage)};
}

}  // namespace wg
