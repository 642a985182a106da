// Ops of the interactive snow layer (seed 001; docs/deformable-snow.md): the sliding
// deformation map read at a world point, the border fade of eq. 3.10-3.11 and glitter
// limited to the specular highlight of eq. 3.9.
#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

#include "nodes/core_library.hpp"
#include "nodes/height_field.hpp"
#include "nodes/lattice_noise.hpp"
#include "nodes/op_registry.hpp"
#include "nodes/pbr_shading.hpp"
#include "nodes/weather_maps.hpp"

namespace wg {

namespace {
// The deformation map's default extent: 1024 texels of 4 cm (snow/snow_window.hpp).
constexpr float kDefaultMapExtent = 40.96f, kDefaultMapTexels = 1024.f;

// Four bilinear taps of the deformation map half a texel apart, averaged. Both maps
// are single-level and read at level 0 in every stage: no derivatives, no anisotropic
// footprint (which lavapipe filters with many more taps).
std::string_view deformationTaps() {
  static const std::string code = [] {
    auto tap = [](const char* offset) {
      return std::string("wg_snow_deformation_texel({position}.xz / {extent} + vec2(") + offset + ") / {texels})";
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
      return std::string("wg_terrain_height_texel(({position}.xz + vec2(") + offset +
             ") - frame_terrainRegion.xy) * frame_terrainRegion.zw).r";
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
vec4 wg_snow_ground(const float h, const float east, const float west, const float north, const float south) {
  const float kStep = 0.5;
  float s = frame_terrainHeightScale;
  return vec4(h * s, wg_safe_normalize(vec3((west - east) * s, (south - north) * s, 2.0 * kStep)));
}
// Open sky over p from the sky-exposure map's occluder height there, by the rule of the
// weather library's exposure (open when nothing is 10 cm above, sheltered under 50 cm),
// one tap without its filtering, so the layer carries no weather code; outside the
// map's region, open.
float wg_snow_sky_open(const vec3 p, const float occluder, const vec2 uv) {
  bool inside = frame_skyExposureRegion.z > 0.0 && all(equal(uv, clamp(uv, 0.0, 1.0)));
  return inside ? 1.0 - smoothstep(p.y + 0.1, p.y + 0.5, occluder) : 1.0;
}
)",
    {&kCoreLibrary, &kWeatherMapLibrary}};

// Seed 3.5.2's sparkles as a field that is continuous in the camera, so glitter does not
// flicker. A sparkle is a point glint at a hashed spot in the middle half of a
// `density` fraction of cells, drawn as a smooth bump (1 - q)^2, q = d' S^-1 d: its own
// spot, kSparkleRadius of a cell in radius, widened by the pixel's footprint (S adds
// r^2 J J', J the screen derivatives of world xz, r = 1.5 pixels), so on screen every
// sparkle is a round disc at least 3 pixels across, never a streak, and never a pixel's
// yes or no. The four cells whose middles surround a point are the only ones whose
// bump can reach it (any other sparkle is at least 0.75 cell away), so nothing pops at
// cell edges. Where pixels are wider, the sparkles come from coarser cells (level n:
// 2^n base cells, each level its own hash salt) so the widened bump still fits; the two
// levels around that size are blended by the fractional level. Cells hash as
// wg_lattice_hash; PCG's LCG step gives the two jitters.
constexpr float kSparkleRadius = 0.25f;  // cells
const ShaderLibrary kSnowGlitterLibrary = {
    "snow_glitter",
    R"(// s: the bump's spread (S's xx, xy, yy) in this level's cells squared.
float wg_sparkle_level(const vec2 g, const float density, const uint salt, const vec3 s) {
  vec2 b = floor(g - 0.5);
  vec4 cx = b.x + vec4(0.0, 1.0, 0.0, 1.0);
  vec4 cy = b.y + vec4(0.0, 0.0, 1.0, 1.0);
  uvec4 h = ((uvec4(ivec4(cx)) * 1597334673u) ^ (uvec4(ivec4(cy)) * 3812015801u ^ salt)) * 1597334673u;
  uvec4 jx = h * 747796405u + 2891336453u;
  uvec4 jy = jx * 747796405u + 2891336453u;
  vec4 lit = 1.0 - step(vec4(density), vec4(h >> 8u) * (1.0 / 16777216.0));
  vec4 dx = g.x - cx - (0.25 + vec4(jx >> 8u) * (0.5 / 16777216.0));
  vec4 dy = g.y - cy - (0.25 + vec4(jy >> 8u) * (0.5 / 16777216.0));
  vec4 q = max(1.0 - (s.z * dx * dx - 2.0 * s.y * dx * dy + s.x * dy * dy) / (s.x * s.z - s.y * s.y), 0.0);
  return dot(lit, q * q);
}
// ex, ey: the world xz a pixel step moves (dFdx, dFdy), 0 on the CPU. A bump's spread in
// base cells is r0^2 I + r^2 J J' (r0 = 0.25 cell, r = 1.5 pixels); level n divides the
// footprint's part by 4^n. At level f - 1 that part's trace is 0.5, so the bump is at
// most sqrt(0.0625 + 0.5) = 0.75 cell in radius; floor(f) and floor(f) + 1 fit too.
float wg_snow_sparkle(const vec2 xz, const float density, const float cellsPerMetre, const vec2 ex, const vec2 ey) {
  vec2 jx = vec2(ex.x, ey.x) * (1.5 * cellsPerMetre), jy = vec2(ex.y, ey.y) * (1.5 * cellsPerMetre);
  vec3 jj = vec3(dot(jx, jx), dot(jx, jy), dot(jy, jy));
  float f = clamp(0.5 * log2(max(jj.x + jj.z, 1e-12)) + 1.5, 0.0, 16.0);
  float n = floor(f);
  vec2 g = xz * cellsPerMetre * exp2(-n);
  vec3 j = jj * exp2(-2.0 * n);
  uint salt = uint(n) * 2654435769u;  // 2^32 / golden ratio
  float sum = 0.0;
  for (int i = 0; i < 2; ++i) {  // a loop, not two copies: half the instructions
    sum += (i == 0 ? 1.0 - (f - n) : f - n) * wg_sparkle_level(g, density, salt, j + vec3(0.0625, 0.0, 0.0625));
    g *= 0.5;
    j *= 0.25;
    salt += 2654435769u;
  }
  return sum;
}
)",
    {}};

// wg_snow_sparkle with no footprint (the CPU evaluator's point): level 0 alone, bumps
// kSparkleRadius of a cell in radius, as the GPU draws where a pixel is far smaller.
float snowSparkle(float x, float z, float density, float cellsPerMetre) {
  float gx = x * cellsPerMetre, gz = z * cellsPerMetre;
  float bx = std::floor(gx - 0.5f), bz = std::floor(gz - 0.5f), sum = 0.f;
  constexpr float kUnit = 1.f / 16777216.f;  // the top 24 bits convert exactly
  for (float cz : {bz, bz + 1.f})
    for (float cx : {bx, bx + 1.f}) {
      std::uint32_t h = latticeHash(static_cast<std::int32_t>(cx), static_cast<std::int32_t>(cz));
      std::uint32_t jx = h * 747796405u + 2891336453u, jz = jx * 747796405u + 2891336453u;
      if (!(static_cast<float>(h >> 8) * kUnit < density)) continue;
      float dx = gx - cx - (0.25f + static_cast<float>(jx >> 8) * (0.5f * kUnit));
      float dz = gz - cz - (0.25f + static_cast<float>(jz >> 8) * (0.5f * kUnit));
      float q = std::max(1.f - (dx * dx + dz * dz) / (kSparkleRadius * kSparkleRadius), 0.f);
      sum += q * q;
    }
  return sum;
}

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
    // texel that holds it (snow/snow_window.hpp). Four bilinear taps half a
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
              V, {&kWeatherMapLibrary}};
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
               "wg_snow_sky_open({position}, wg_sky_exposure_texel("
               "({position}.xz - frame_skyExposureRegion.xy) * frame_skyExposureRegion.zw).r, "
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
  // with the sun's half vector, a smooth lobe), so never in shadow: the sun shadow map's
  // visibility multiplies it (fragment stage only). The sparkles themselves are a field
  // filtered over the pixel's footprint (kSnowGlitterLibrary).
  ops.push_back({"snow_glitter", "snow",
                 "eq. 3.9: sparkles * pow(max(N.H, 0), shininess) * sun * shadow; emissive glints of snow crystals, "
                 "smooth bumps fixed in the world and at least a pixel in radius, so they do not flicker; sparkle masks "
                 "them (fragment stage)",
                 {{"normal", PortType::Vec3, std::nullopt},
                  {"position", PortType::Vec3, std::nullopt},
                  {"sparkle", PortType::Float, Value::scalar(1.f)},
                  {"shininess", PortType::Float, Value::scalar(64.f), 1.f, 4096.f},
                  {"density", PortType::Float, Value::scalar(0.15f), 0.f, 1.f},
                  {"cellsPerMetre", PortType::Float, Value::scalar(60.f), 0.f, 1e5f}},
                 ValueRule::Fixed, ValueType::Float,
                 "({sparkle} * wg_snow_sparkle({position}.xz, {density}, {cellsPerMetre}, dFdx({position}.xz), dFdy({position}.xz)) * "
                 "pow(max(dot({normal}, wg_safe_normalize(frame_sunDirection + wg_safe_normalize("
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
                   float sparkles = in[2].x() * snowSparkle(p.x, p.z, in[4].x(), in[5].x());
                   return Value::scalar(sparkles * highlight * f.sunIntensity * c.surface->sunVisibility);
                 },
                 V, {&kPbrShadingLibrary, &kSnowGlitterLibrary}});
}

}  // namespace wg
