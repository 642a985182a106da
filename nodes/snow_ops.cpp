// Ops of the interactive snow layer (seed 001; docs/deformable-snow.md): the sliding
// deformation map read at a world point, the border fade of eq. 3.10-3.11 and glitter
// limited to the specular highlight of eq. 3.9.
#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <string>

#include "nodes/core_library.hpp"
#include "nodes/height_field.hpp"
#include "nodes/op_registry.hpp"
#include "nodes/pbr_shading.hpp"

namespace wg {

namespace {
// The deformation map's default extent: 1024 texels of 4 cm (runtime/snow/snow_window.hpp).
constexpr float kDefaultMapExtent = 40.96f, kDefaultMapTexels = 1024.f;

// Four bilinear taps of the deformation map half a texel apart, averaged. Both maps
// are single-level and read at level 0 in every stage: no derivatives, no anisotropic
// footprint (which lavapipe filters with many more taps).
std::string_view deformationTaps() {
  static const std::string code = [] {
    auto tap = [](const char* offset) {
      return std::string("textureLod(sampler2D(wg_snow_deformation_map, wg_snow_deformation_sampler), "
                         "{position}.xz / {extent} + vec2(") +
             offset + ") / {texels}, 0.0)";
    };
    return "(0.25 * (" + tap("-0.5, -0.5") + " + " + tap("0.5, -0.5") + " + " + tap("-0.5, 0.5") + " + " +
           tap("0.5, 0.5") + "))";
  }();
  return code;
}

// The terrain under the layer: its height map read at the point and half a metre
// east, west, north and south of it (central differences for the normal). The map's
// zero is world y = 0 (the snowfield lays its terrain out so), frame_terrainHeightScale
// metres per unit.
constexpr float kGroundStep = 0.5f;  // m; wg_snow_ground's kStep
std::string_view groundTaps() {
  static const std::string code = [] {
    auto tap = [](const char* offset) {
      return std::string("textureLod(sampler2D(wg_terrain_height_map, wg_terrain_height_sampler), ({position}.xz + vec2(") +
             offset + ") - frame_terrainRegion.xy) * frame_terrainRegion.zw, 0.0).r";
    };
    return "wg_snow_ground(" + tap("0.0, 0.0") + ", " + tap("0.5, 0.0") + ", " + tap("-0.5, 0.0") + ", " +
           tap("0.0, 0.5") + ", " + tap("0.0, -0.5") + ")";
  }();
  return code;
}

const ShaderLibrary kSnowGroundLibrary = {
    "snow_ground",
    R"(// Height (m) and the level layer's tangent-space normal (x along +x, y along +z) of
// the terrain, from its map at the point and kStep east, west, north and south.
vec4 wg_snow_ground(float h, float east, float west, float north, float south) {
  const float kStep = 0.5;
  float s = frame_terrainHeightScale;
  return vec4(h * s, wg_safe_normalize(vec3((west - east) * s, (south - north) * s, 2.0 * kStep)));
}
// Open sky over p from the sky-exposure map's occluder height there, by the rule of the
// weather library's exposure (open when nothing is 10 cm above, sheltered under 50 cm),
// one tap without its filtering, so the layer carries no weather code; outside the
// map's region, open.
float wg_snow_sky_open(vec3 p, float occluder, vec2 uv) {
  bool inside = frame_skyExposureRegion.z > 0.0 && all(equal(uv, clamp(uv, 0.0, 1.0)));
  return inside ? 1.0 - smoothstep(p.y + 0.1, p.y + 0.5, occluder) : 1.0;
}
)",
    {&kCoreLibrary}};

// Seed 3.5.2's sparkle, kept stable as the camera moves. Where a pixel spans more than
// one sparkle cell, the cell its centre hits would change from frame to frame (flicker):
// there the sparkle comes from coarser cells, each at least a pixel wide and fixed in
// the world, lit with the same density. The CPU evaluator's point has no footprint, so
// it always takes the graph's own sparkle.
const ShaderLibrary kSnowGlitterLibrary = {
    "snow_glitter",
    R"(float wg_snow_sparkle(float sparkle, float density, vec2 xz, float cellsPerMetre) {
  float cellsPerPixel = cellsPerMetre * max(fwidth(xz.x), fwidth(xz.y));
  if (!(cellsPerPixel > 1.0)) return sparkle;
  float lod = min(ceil(log2(cellsPerPixel)), 16.0);
  vec2 cell = floor(xz * (cellsPerMetre / exp2(lod)));
  float h = fract(sin(dot(cell, vec2(12.9898, 78.233)) + lod * 7.13) * 43758.5453);
  return step(1.0 - density, h);
}
)",
    {}};

glm::vec4 snowGround(const EvalContext& c, glm::vec3 p) {
  auto height = [&](float dx, float dz) {
    if (!c.terrainHeight) return 0.f;
    const auto& r = c.frame->terrainRegion;
    return c.terrainHeight->sample((p.x + dx - r[0]) * r[2], (p.z + dz - r[1]) * r[3]) * c.frame->terrainHeightScale;
  };
  float e = kGroundStep;
  glm::vec3 n(height(-e, 0.f) - height(e, 0.f), height(0.f, -e) - height(0.f, e), 2.f * e);
  return {height(0.f, 0.f), glm::normalize(n)};
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
  {
    OpDef ground{"snow_ground", "snow",
                 "the terrain under a point: its height (m, the terrain map times frame terrainHeightScale) and "
                 "normal in the tangent space of a level layer (x along +x, y along +z, z up)",
                 {{"position", PortType::Vec3, std::nullopt}},
                 ValueRule::Fixed, ValueType::Vec4, groundTaps(), "",
                 {{"height", ".x"}, {"normal", ".yzw"}, {"flatness", ".w"}},
                 [](const Value* in, const EvalContext& c) {
                   glm::vec4 g = snowGround(c, {in[0].v[0], in[0].v[1], in[0].v[2]});
                   return Value::vec4(g.x, g.y, g.z, g.w);
                 },
                 V, {&kSnowGroundLibrary}};
    ground.weatherMaps = {"terrainHeight"};
    ops.push_back(std::move(ground));
  }
  {
    OpDef open{"snow_sky_open", "snow",
               "open sky over a point (1) or an overhang above it (0), from the sky-exposure map's occluder height",
               {{"position", PortType::Vec3, std::nullopt}},
               ValueRule::Fixed, ValueType::Float,
               "wg_snow_sky_open({position}, textureLod(sampler2D(wg_sky_exposure_map, wg_sky_exposure_sampler), "
               "({position}.xz - frame_skyExposureRegion.xy) * frame_skyExposureRegion.zw, 0.0).r, "
               "({position}.xz - frame_skyExposureRegion.xy) * frame_skyExposureRegion.zw)",
               "", singleOutput(),
               [](const Value*, const EvalContext& c) { return Value::scalar(c.surface->skyExposure); },
               V, {&kSnowGroundLibrary}};
    open.weatherMaps = {"skyExposure"};
    ops.push_back(std::move(open));
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
  // multiplies it (fragment stage only); the sparkle is kept stable (kSnowGlitterLibrary).
  ops.push_back({"snow_glitter", "snow",
                 "eq. 3.9: sparkle * pow(max(N.H, 0), shininess) * sun * shadow; emissive glints of snow crystals, "
                 "sparkle cells at least a pixel wide, fixed in the world (fragment stage)",
                 {{"normal", PortType::Vec3, std::nullopt},
                  {"position", PortType::Vec3, std::nullopt},
                  {"sparkle", PortType::Float, std::nullopt},
                  {"shininess", PortType::Float, Value::scalar(64.f), 1.f, 4096.f},
                  {"density", PortType::Float, Value::scalar(0.03f), 0.f, 1.f},
                  {"cellsPerMetre", PortType::Float, Value::scalar(60.f), 0.f, 1e5f}},
                 ValueRule::Fixed, ValueType::Float,
                 "(wg_snow_sparkle({sparkle}, {density}, {position}.xz, {cellsPerMetre}) * pow(max(dot({normal}, "
                 "wg_safe_normalize(frame_sunDirection + wg_safe_normalize("
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
                 V, {&kPbrShadingLibrary, &kSnowGlitterLibrary}});
}

}  // namespace wg
