// Ops of the interactive snow layer (seed 001; docs/deformable-snow.md): the sliding
// deformation map read at a world point, the border fade of eq. 3.10-3.11 and glitter
// limited to the specular highlight of eq. 3.9.
#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <string>

#include "nodes/op_registry.hpp"
#include "nodes/pbr_shading.hpp"

namespace wg {

namespace {
// The deformation map's default extent: 1024 texels of 4 cm (runtime/snow/snow_window.hpp).
constexpr float kDefaultMapExtent = 40.96f, kDefaultMapTexels = 1024.f;

// Four bilinear taps of the deformation map half a texel apart, averaged.
std::string_view deformationTaps() {
  static const std::string code = [] {
    auto tap = [](const char* offset) {
      return std::string("{@sampleFn}(sampler2D(wg_snow_deformation_map, wg_snow_deformation_sampler), "
                         "{position}.xz / {extent} + vec2(") +
             offset + ") / {texels}{@lodArg})";
    };
    return "(0.25 * (" + tap("-0.5, -0.5") + " + " + tap("0.5, -0.5") + " + " + tap("-0.5, 0.5") + " + " +
           tap("0.5, 0.5") + "))";
  }();
  return code;
}

float smoothstep(float e0, float e1, float x) {
  float t = std::clamp((x - e0) / (e1 - e0), 0.f, 1.f);
  return t * t * (3.f - 2.f * t);
}
}  // namespace

void appendSnowOps(std::vector<OpDef>& ops) {
  constexpr auto V = OpPurity::Varying;
  {
    // The map is toroidal: world xz / extent wraps with the repeat sampler onto the
    // texel that holds it (runtime/snow/snow_window.hpp). Four bilinear taps half a
    // texel apart (a 3 x 3 tent): a print's wall is steeper than one 4 cm texel, and a
    // single tap per vertex or pixel shows the texel staircase along its edge.
    OpDef map{"snow_deformation", "snow",
              "the deformation map at a world point, smoothed over a texel: height offset (m) and the normal in "
              "tangent space of a level layer (x along +x, y along +z)",
              {{"position", PortType::Vec3, std::nullopt},
               {"extent", PortType::Float, Value::scalar(kDefaultMapExtent), 1e-3f, 1e5f},
               {"texels", PortType::Float, Value::scalar(kDefaultMapTexels), 1.f, 65536.f}},
              ValueRule::Fixed, ValueType::Vec4,
              deformationTaps(),
              "",
              // Texel: (height, world normal x, y, z); a level layer's tangent frame is
              // (+x, +z, +y), so its tangent-space normal is .ywz.
              {{"height", ".x"}, {"normal", ".ywz"}, {"worldNormal", ".yzw"}},
              [](const Value*, const EvalContext& c) {
                const auto& d = c.surface->snowDeformation;
                return Value::vec4(d[0], d[1], d[2], d[3]);
              },
              V};
    map.weatherMaps = {"snowDeformation"};
    ops.push_back(std::move(map));
  }
  ops.push_back({"snow_border_fade", "snow",
                 "eq. 3.10-3.11: 1 - smoothstep(near, far, distance(position.xz, camera.xz))",
                 {{"position", PortType::Vec3, std::nullopt},
                  {"near", PortType::Float, Value::scalar(14.f), 0.f, 1e5f},
                  {"far", PortType::Float, Value::scalar(19.f), 0.f, 1e5f}},
                 ValueRule::Fixed, ValueType::Float,
                 "(1.0 - smoothstep({near}, max({far}, {near} + 1e-3), distance({position}.xz, frame_cameraPosition.xz)))", "",
                 singleOutput(),
                 [](const Value* in, const EvalContext& c) {
                   glm::vec2 p(in[0].v[0], in[0].v[2]), eye(c.frame->cameraPosition[0], c.frame->cameraPosition[2]);
                   float nearFade = in[1].x(), farFade = std::max(in[2].x(), nearFade + 1e-3f);
                   return Value::scalar(1.f - smoothstep(nearFade, farFade, glm::distance(p, eye)));
                 },
                 V});
  // Seed 3.5.2: sparkles only inside the specular highlight (eq. 3.9, Blinn-Phong
  // with the sun's half vector), so never in shadow: the sun shadow map's visibility
  // multiplies it (fragment stage only).
  ops.push_back({"snow_glitter", "snow",
                 "eq. 3.9: sparkle * pow(max(N.H, 0), shininess) * sun * shadow; emissive glints of snow crystals",
                 {{"normal", PortType::Vec3, std::nullopt},
                  {"position", PortType::Vec3, std::nullopt},
                  {"sparkle", PortType::Float, std::nullopt},
                  {"shininess", PortType::Float, Value::scalar(64.f), 1.f, 4096.f}},
                 ValueRule::Fixed, ValueType::Float,
                 "({sparkle} * pow(max(dot({normal}, wg_safe_normalize(frame_sunDirection + wg_safe_normalize("
                 "frame_cameraPosition - {position}))), 0.0), {shininess}) * frame_sunIntensity * "
                 "wg_sun_shadow({position}, {normal}))",
                 "",
                 singleOutput(),
                 [](const Value* in, const EvalContext& c) {
                   glm::vec3 n(in[0].v[0], in[0].v[1], in[0].v[2]), p(in[1].v[0], in[1].v[1], in[1].v[2]);
                   const FrameState& f = *c.frame;
                   glm::vec3 sun(f.sunDirection[0], f.sunDirection[1], f.sunDirection[2]);
                   glm::vec3 eye(f.cameraPosition[0], f.cameraPosition[1], f.cameraPosition[2]);
                   glm::vec3 toEye = eye - p;
                   toEye = glm::length(toEye) > 0.f ? glm::normalize(toEye) : toEye;
                   glm::vec3 h = sun + toEye;
                   h = glm::length(h) > 0.f ? glm::normalize(h) : h;
                   float highlight = std::pow(std::max(glm::dot(n, h), 0.f), in[3].x());
                   return Value::scalar(in[2].x() * highlight * f.sunIntensity * c.surface->sunVisibility);
                 },
                 V, {&kPbrShadingLibrary}});
}

}  // namespace wg
