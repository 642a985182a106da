// Weather ops (seed 000, chapter 3): one per equation, plus the per-effect coverage
// ops the weather injection pass composes. CPU semantics live in nodes/weather_model.cpp
// and shader code in nodes/weather_shader_library.cpp; each op names its equation.
#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

#include "nodes/height_field.hpp"
#include "nodes/op_registry.hpp"
#include "nodes/texture_image.hpp"
#include "nodes/texture_sampling.hpp"
#include "nodes/weather_model.hpp"
#include "nodes/weather_noise.hpp"
#include "nodes/weather_shader_library.hpp"

namespace wg {

namespace {
using namespace weather;

glm::vec3 v3(const Value& v) { return {v.v[0], v.v[1], v.v[2]}; }
glm::vec4 v4(const Value& v) { return {v.v[0], v.v[1], v.v[2], v.v[3]}; }
Value out3(glm::vec3 v) { return Value::vec3(v.x, v.y, v.z); }
glm::vec3 arr3(const std::array<float, 3>& a) { return {a[0], a[1], a[2]}; }

PortSpec vec3Required(std::string_view name) { return {name, PortType::Vec3, std::nullopt}; }
PortSpec floatRequired(std::string_view name) { return {name, PortType::Float, std::nullopt}; }
PortSpec floatPort(std::string_view name, float dflt, float lo = -1e30f, float hi = 1e30f) {
  return {name, PortType::Float, Value::scalar(dflt), lo, hi};
}
PortSpec vec3Port(std::string_view name, glm::vec3 d) { return {name, PortType::Vec3, Value::vec3(d.x, d.y, d.z)}; }
PortSpec vec4Port(std::string_view name, glm::vec4 d) { return {name, PortType::Vec4, Value::vec4(d.x, d.y, d.z, d.w)}; }

SnowShape shapeFrom(const Value& weights, const Value& shape, const Value* terms) {
  SnowShape s;
  s.weights = v4(weights);
  s.minHeight = shape.v[0];
  s.maxHeight = shape.v[1];
  s.inclinationIntensity = shape.v[2];
  if (terms) s.terms = v4(*terms);
  return s;
}

// The fragment stage's frame at a surface point: the unit normal, and the tangent made
// orthogonal to it (w: the bitangent's sign).
std::pair<glm::vec3, glm::vec4> tangentFrame(const SurfacePoint& s) {
  glm::vec3 n = arr3(s.worldNormal);
  n *= 1.f / std::sqrt(std::max(glm::dot(n, n), 1e-12f));  // wg_safe_normalize: a zero normal stays zero
  glm::vec3 t(s.tangent[0], s.tangent[1], s.tangent[2]);
  glm::vec3 tangent = t - n * glm::dot(n, t);
  float len = glm::length(tangent);
  return {n, glm::vec4(len > 1e-6f ? tangent / len : glm::vec3(0.f), s.tangent[3])};
}

OpDef weatherOp(std::string_view name, std::string_view summary, std::vector<PortSpec> inputs, ValueType type,
                std::string_view glsl, CpuEval eval, OpPurity purity = OpPurity::Pure) {
  // The library text is shared; only vector type names differ, and templates use none.
  // It samples the noise texture (eq. 3.6's flow, the ripple), so every op that emits it
  // makes the material declare that map.
  OpDef op{name, "weather", summary, std::move(inputs), ValueRule::Fixed, type, glsl, "", singleOutput(), eval, purity,
           {&kWeatherLibrary}};
  op.weatherMaps = {"weatherNoise"};
  return op;
}

const SnowShape kDefaultShape;
const glm::vec4 kDefaultShapeVector{kDefaultShape.minHeight, kDefaultShape.maxHeight, kDefaultShape.inclinationIntensity, 0.f};
}  // namespace

void appendWeatherOps(std::vector<OpDef>& ops) {
  constexpr auto F = ValueType::Float;
  constexpr auto V3 = ValueType::Vec3;
  constexpr auto V = OpPurity::Varying;

  ops.push_back(weatherOp("weather_inclination", "eq. 3.4: Clamp(N.up + (Nd.up) intensity)^3",
                          {vec3Required("normal"), vec3Required("detailNormal"), floatPort("intensity", 0.5f, 0.f, 4.f)}, F,
                          "wg_inclination({normal}, {detailNormal}, {intensity})",
                          [](const Value* in, const EvalContext&) {
                            return Value::scalar(inclination(v3(in[0]), v3(in[1]), in[2].x()));
                          }));
  ops.push_back(weatherOp("weather_sun", "eq. 3.5: less cover on faces that get more sun than level ground",
                          {vec3Required("normal")}, F, "wg_sun_facing({normal}, frame_sunDirection, frame_sunMelt)",
                          [](const Value* in, const EvalContext& c) {
                            return Value::scalar(sunFacing(v3(in[0]), arr3(c.frame->sunDirection), c.frame->sunMelt));
                          },
                          V));
  ops.push_back(weatherOp("weather_wind", "eq. 3.6-3.7: two-phase panning wind flow and its influence",
                          {vec3Required("normal"), vec3Required("position")}, F,
                          "wg_wind_influence({normal}, {position}.xz, frame_windDirection, frame_windIntensity, frame_time)",
                          [](const Value* in, const EvalContext& c) {
                            const FrameState& f = *c.frame;
                            return Value::scalar(windInfluence(v3(in[0]), {in[1].v[0], in[1].v[2]},
                                                               {f.windDirection[0], f.windDirection[1]}, f.windIntensity, f.time));
                          },
                          V));
  // f_wind alone, for the effect ops' windFlow port: 4 m flow cells, smooth across a
  // triangle, so the vertex stage computes it and the fragment stage reads it interpolated.
  ops.push_back(weatherOp("weather_wind_flow", "eq. 3.6: the two-phase panning wind flow f_wind at a point",
                          {vec3Required("position")}, F, "wg_wind_flow({position}.xz, frame_windDirection, frame_time)",
                          [](const Value* in, const EvalContext& c) {
                            const FrameState& f = *c.frame;
                            return Value::scalar(windFlow({in[0].v[0], in[0].v[2]}, {f.windDirection[0], f.windDirection[1]}, f.time));
                          },
                          V));
  ops.back().rate = OpRate::Vertex;
  ops.push_back(weatherOp("weather_height", "eq. 3.8: Clamp((y - minHeight) / (maxHeight - minHeight))",
                          {vec3Required("position"), floatPort("minHeight", -50.f), floatPort("maxHeight", 50.f)}, F,
                          "wg_height({position}.y, {minHeight}, {maxHeight})", [](const Value* in, const EvalContext&) {
                            return Value::scalar(height(in[0].v[1], in[1].x(), in[2].x()));
                          }));
  ops.push_back(weatherOp("weather_height_inverted", "eq. 3.9: 1 - eq. 3.8 (moss prefers low ground)",
                          {vec3Required("position"), floatPort("minHeight", -50.f), floatPort("maxHeight", 50.f)}, F,
                          "wg_height_inverted({position}.y, {minHeight}, {maxHeight})",
                          [](const Value* in, const EvalContext&) {
                            return Value::scalar(heightInverted(in[0].v[1], in[1].x(), in[2].x()));
                          }));
  ops.push_back(weatherOp("weather_displacement", "eq. 3.10: (Clamp(noise + 0.75) progress maxSnowHeight) N",
                          {floatRequired("noise"), floatRequired("progress"), floatPort("maxSnowHeight", 0.25f, 0.f, 10.f),
                           vec3Required("normal")},
                          V3, "wg_snow_displacement({noise}, {progress}, {maxSnowHeight}, {normal})",
                          [](const Value* in, const EvalContext&) {
                            return out3(snowDisplacement(in[0].x(), in[1].x(), in[2].x(), v3(in[3])));
                          }));
  ops.push_back(weatherOp("terrain_coord", "eq. 3.11: world position to terrain height-map uv", {vec3Required("position")},
                          ValueType::Vec2, "wg_terrain_coord({position})",
                          [](const Value* in, const EvalContext& c) {
                            const auto& r = c.frame->terrainRegion;
                            return Value::vec2((in[0].v[0] - r[0]) * r[2], (in[0].v[2] - r[1]) * r[3]);
                          },
                          V));
  ops.back().rate = OpRate::Any;
  {
    OpDef height = weatherOp("terrain_height", "the shared terrain height map at uv (0 where none is bound)",
                             {{"uv", PortType::Vec2, std::nullopt}}, F,
                             "wg_terrain_height_texel({uv}).r",
                             [](const Value* in, const EvalContext& c) {
                               if (!c.terrainHeight) return Value::scalar(0.f);
                               return Value::scalar(c.terrainHeight->sample(in[0].v[0], in[0].v[1]));
                             },
                             V);
    height.weatherMaps.push_back("terrainHeight");
    height.rate = OpRate::Any;  // the map has one level: mip 0 in either stage
    ops.push_back(std::move(height));
  }
  ops.push_back(weatherOp("weather_terrain_slope", "eq. 3.12: slope from the height map shifted by 0.05",
                          {floatRequired("h0"), floatRequired("hShiftU"), floatRequired("hShiftV"), floatPort("intensity", 1.f)},
                          V3, "wg_terrain_slope({h0}, {hShiftU}, {hShiftV}, {intensity})",
                          [](const Value* in, const EvalContext&) {
                            return out3(terrainSlope(in[0].x(), in[1].x(), in[2].x(), in[3].x()));
                          }));
  // Differences over a twentieth of the height map: smooth across any triangle.
  ops.back().rate = OpRate::Vertex;
  ops.push_back(weatherOp("weather_terrain_orientation", "eq. 3.13: ((slope (1,1,0)) . N) (TN . (0,0,1)) intensity",
                          {vec3Required("slope"), vec3Required("normal"), floatPort("tangentNormalZ", 1.f), floatPort("intensity", 1.f)},
                          F, "wg_terrain_orientation({slope}, {normal}, {tangentNormalZ}, {intensity})",
                          [](const Value* in, const EvalContext&) {
                            return Value::scalar(terrainOrientation(v3(in[0]), v3(in[1]), in[2].x(), in[3].x()));
                          }));
  ops.push_back(weatherOp("weather_transition", "eq. 3.14: Clamp(noise - 1 + 3 progress)",
                          {floatRequired("noise"), floatRequired("progress")}, F, "wg_transition({noise}, {progress})",
                          [](const Value* in, const EvalContext&) { return Value::scalar(transition(in[0].x(), in[1].x())); }));
  ops.push_back(weatherOp("weather_prediction", "eq. 3.1: Clamp(inc (w1 sun w3 height + w4 terrain + w2 wind))",
                          {floatRequired("inclination"), floatPort("sun", 1.f), floatPort("height", 1.f), floatPort("terrain", 0.f),
                           floatPort("wind", 0.f), vec4Port("weights", kDefaultShape.weights)},
                          F, "wg_prediction({inclination}, {sun}, {height}, {terrain}, {wind}, {weights})",
                          [](const Value* in, const EvalContext&) {
                            return Value::scalar(prediction(in[0].x(), in[1].x(), in[2].x(), in[3].x(), in[4].x(), v4(in[5])));
                          }));
  ops.push_back(weatherOp("weather_wetness", "eq. 3.15: wetness level where T > 0, scaled by sky exposure",
                          {floatPort("exposure", 1.f, 0.f, 1.f)}, F,
                          "wg_wetness(frame_temperature, frame_wetnessLevel, {exposure})",
                          [](const Value* in, const EvalContext& c) {
                            return Value::scalar(wetness(c.frame->temperature, c.frame->wetnessLevel, in[0].x()));
                          },
                          V));
  ops.push_back(weatherOp("weather_wet_diffuse", "eq. 3.16 by porosity: diffuse * Lerp(1, 0.7, p (1 - metallic))",
                          {vec3Required("diffuse"), floatRequired("p"), floatPort("metallic", 0.f, 0.f, 1.f)}, V3,
                          "wg_wet_diffuse({diffuse}, {p}, {metallic})",
                          [](const Value* in, const EvalContext&) { return out3(wetDiffuse(v3(in[0]), in[1].x(), in[2].x())); }));
  ops.push_back(weatherOp("weather_wet_roughness",
                          "eq. 3.17 by porosity: max(Clamp(roughness - p), metallic * min(roughness, 0.15))",
                          {floatRequired("roughness"), floatRequired("p"), floatPort("metallic", 0.f, 0.f, 1.f)}, F,
                          "wg_wet_roughness({roughness}, {p}, {metallic})",
                          [](const Value* in, const EvalContext&) {
                            return Value::scalar(wetRoughness(in[0].x(), in[1].x(), in[2].x()));
                          }));
  // The CPU evaluator sees one point, no pixel footprint: the roughness as it is.
  ops.push_back(weatherOp("weather_specular_aa",
                          "specular anti-aliasing: roughness widened by the tangent normal's variance over the pixel "
                          "in lit frames (fragment stage)",
                          {floatRequired("roughness"), vec3Port("normal", {0.f, 0.f, 1.f})}, F,
                          "wg_specular_aa({roughness}, dFdx({normal}), dFdy({normal}))",
                          [](const Value* in, const EvalContext&) { return Value::scalar(in[0].x()); }));
  ops.push_back(weatherOp("weather_wet_normal", "eq. 3.18: tangent normal + panning ripple while it rains, faded by the pixel footprint (fragment stage)",
                          {vec3Required("normal"), vec3Required("position"), floatRequired("p")}, V3,
                          "wg_wet_normal({normal}, {position}.xz, {p}, frame_precipitation, frame_time, fwidth({position}.xz))",
                          [](const Value* in, const EvalContext& c) {
                            return out3(wetNormal(v3(in[0]), {in[1].v[0], in[1].v[2]}, in[2].x(), c.frame->precipitation, c.frame->time));
                          },
                          V));
  ops.push_back(weatherOp("weather_detail_mask", "eq. 3.19: Clamp(desaturate(diffuse, 1)), darker fills first",
                          {vec3Required("diffuse")}, F, "wg_detail_mask({diffuse})",
                          [](const Value* in, const EvalContext&) { return Value::scalar(detailMask(v3(in[0]))); }));
  ops.push_back(weatherOp("weather_snow_albedo", "eq. 3.19 + Table 4.1: snow from the diffuse map, reflectance 0.90-0.95",
                          {vec3Required("diffuse")}, V3, "wg_snow_albedo({diffuse})",
                          [](const Value* in, const EvalContext&) { return out3(snowAlbedo(v3(in[0]))); }));
  ops.push_back(weatherOp("weather_moss_albedo", "detail mask * green, Table 4.1 grass band 0.25-0.53",
                          {vec3Required("diffuse")}, V3, "wg_moss_albedo({diffuse})",
                          [](const Value* in, const EvalContext&) { return out3(mossAlbedo(v3(in[0]))); }));
  ops.push_back(weatherOp("weather_ice_albedo",
                          "Table 4.1 ocean-ice band 0.5-0.7: darker diffuse fills first, cracks and bubbles (where the "
                          "frozen surface's tangent normal bends) at the band's top",
                          {vec3Required("diffuse"), vec3Port("normal", {0.f, 0.f, 1.f})}, V3, "wg_ice_albedo({diffuse}, {normal})",
                          [](const Value* in, const EvalContext&) { return out3(iceAlbedo(v3(in[0]), v3(in[1]))); }));
  ops.push_back(weatherOp("weather_frost_mask", "eq. 3.20: (1 - frostMap)^Lerp(0, 5, 1 - frost)",
                          {floatRequired("frostMap"), floatRequired("frost")}, F, "wg_frost_mask({frostMap}, {frost})",
                          [](const Value* in, const EvalContext&) { return Value::scalar(frostMask(in[0].x(), in[1].x())); }));
  ops.push_back(weatherOp("weather_puddle_mask", "section 5.1.2: within 8 degrees of up, shaped by high-contrast noise",
                          {vec3Required("normal"), floatRequired("noise"), floatRequired("level")}, F,
                          "wg_puddle_mask({normal}, {noise}, {level})", [](const Value* in, const EvalContext&) {
                            return Value::scalar(puddleMask(v3(in[0]), in[1].x(), in[2].x()));
                          }));
  ops.push_back(weatherOp("tangent_to_world", "tangent-space normal to world space", {vec3Required("normal")}, V3,
                          "wg_tangent_to_world({normal}, {@worldNormal}, {@worldTangent})",
                          [](const Value* in, const EvalContext& c) {
                            auto [n, t] = tangentFrame(*c.surface);
                            glm::vec3 tangent(t);
                            glm::vec3 b = glm::cross(n, tangent) * t.w;
                            glm::vec3 m = tangent * in[0].v[0] + b * in[0].v[1] + n * in[0].v[2];
                            float ml = glm::length(m);
                            return out3(ml > 1e-6f ? m / ml : glm::vec3(0.f));
                          },
                          V));
  ops.push_back(weatherOp("weather_noise_relief",
                          "a layer's own relief: the tangent-space normal of the transition noise read as a height field "
                          "of `amplitude` metres (snow 0.25, ice 0.04)",
                          {vec3Required("position"), floatRequired("height"), floatPort("amplitude", 0.25f, 0.f, 4.f)}, V3,
                          "wg_noise_relief({position}, {height}, {amplitude}, {@worldNormal}, {@worldTangent})",
                          [](const Value* in, const EvalContext& c) {
                            auto [n, tangent] = tangentFrame(*c.surface);
                            return out3(noiseRelief(v3(in[0]), in[1].x(), in[2].x(), n, tangent));
                          },
                          V));
  {
    OpDef exposure = weatherOp("sky_exposure", "open sky above the point: 1 exposed, 0 under a roof (shared map)",
                               {vec3Required("position")}, F,
                               "wg_exposure_from_map({position}, {@worldNormal}, "
                               "wg_sky_exposure_gather(wg_sky_exposure_uv({position}, {@worldNormal})))",
                               [](const Value*, const EvalContext& c) { return Value::scalar(c.surface->skyExposure); }, V);
    exposure.weatherMaps.push_back("skyExposure");
    ops.push_back(std::move(exposure));
  }

  ops.push_back({"weather_levels", "weather", "the accumulated levels from the weather state", {}, ValueRule::Fixed,
                 ValueType::Vec4, "vec4(frame_snowLevel, frame_wetnessLevel, frame_mossLevel, frame_frostLevel)", "",
                 {{"snow", ".x"}, {"wetness", ".y"}, {"moss", ".z"}, {"frost", ".w"}},
                 [](const Value*, const EvalContext& c) {
                   const FrameState& f = *c.frame;
                   return Value::vec4(f.snowLevel, f.wetnessLevel, f.mossLevel, f.frostLevel);
                 },
                 V});
  ops.push_back({"weather_conditions", "weather", "temperature (C), precipitation, wind and sun intensity", {},
                 ValueRule::Fixed, ValueType::Vec4,
                 "vec4(frame_temperature, frame_precipitation, frame_windIntensity, frame_sunIntensity)", "",
                 {{"temperature", ".x"}, {"precipitation", ".y"}, {"windIntensity", ".z"}, {"sunIntensity", ".w"}},
                 [](const Value*, const EvalContext& c) {
                   const FrameState& f = *c.frame;
                   return Value::vec4(f.temperature, f.precipitation, f.windIntensity, f.sunIntensity);
                 },
                 V});

  // The shared noise texture (nodes/weather_noise.hpp): one lookup at a point serves
  // every effect's eq. 3.14 transition (and eq. 3.10's displacement noise) and the puddles.
  ops.push_back({"weather_noise", "weather",
                 "the shared weather noise texture at a world point: eq. 3.14's transition noise (r), eq. 3.6's flow (g), "
                 "the eq. 3.18 ripple (b), puddle shapes (a)",
                 {vec3Required("position")}, ValueRule::Fixed, ValueType::Vec4, "wg_weather_noise_at({position})", "",
                 {{"out", ""}, {"transition", ".x"}, {"flow", ".y"}, {"ripple", ".z"}, {"puddle", ".w"}},
                 [](const Value* in, const EvalContext&) {
                   glm::vec4 n = noiseAt(v3(in[0]));
                   return Value::vec4(n.x, n.y, n.z, n.w);
                 },
                 V, {&kWeatherNoiseLibrary}, {"weatherNoise"}});

  // Effect ops: each early-outs while its level is 0.
  ops.push_back(weatherOp("weather_snow_coverage",
                          "snow cover: eq. 3.1 prediction (windFlow: eq. 3.6's f_wind, weather_wind_flow), eq. 3.14 noisy "
                          "edges, detail mask; melting snow in patches (patchNoise: the shared noise's flow channel), "
                          "their edges widened by the pixel footprint where antiAliasing is 1 (the CPU's point has none)",
                          {vec3Required("normal"), vec3Required("detailNormal"), vec3Required("position"), vec3Required("diffuse"),
                           floatPort("terrain", 0.f), floatPort("windFlow", 0.f), floatPort("exposure", 1.f, 0.f, 1.f),
                           vec4Port("weights", kDefaultShape.weights), vec4Port("shape", kDefaultShapeVector),
                           vec4Port("terms", kDefaultShape.terms), floatRequired("noise"), floatPort("patchNoise", 0.5f, 0.f, 1.f),
                           floatPort("antiAliasing", 0.f, 0.f, 1.f)},
                          F,
                          "wg_snow_coverage({normal}, {detailNormal}, {position}, {diffuse}, {terrain}, {windFlow}, {exposure}, "
                          "{weights}, {shape}, {terms}, {noise}, {patchNoise}, "
                          "{antiAliasing} > 0.5 ? fwidth({position}.xz) : vec2(0.0))",
                          [](const Value* in, const EvalContext& c) {
                            return Value::scalar(snowCoverage(*c.frame, v3(in[0]), v3(in[1]), v3(in[2]), v3(in[3]), in[4].x(),
                                                              in[5].x(), in[6].x(), shapeFrom(in[7], in[8], &in[9]), in[10].x(),
                                                              in[11].x()));
                          },
                          V));
  ops.push_back(weatherOp("weather_snow_offset", "snow displacement along the normal (eq. 3.10), vertex stage",
                          {vec3Required("normal"), vec3Required("position"), floatPort("windFlow", 0.f),
                           floatPort("exposure", 1.f, 0.f, 1.f), vec4Port("weights", kDefaultShape.weights),
                           vec4Port("shape", kDefaultShapeVector), vec4Port("terms", kDefaultShape.terms),
                           floatPort("maxSnowHeight", 0.25f, 0.f, 10.f), floatRequired("noise")},
                          V3,
                          "wg_snow_offset({normal}, {position}, {windFlow}, {exposure}, {weights}, {shape}, {terms}, "
                          "{maxSnowHeight}, {noise})",
                          [](const Value* in, const EvalContext& c) {
                            return out3(snowOffset(*c.frame, v3(in[0]), v3(in[1]), in[2].x(), in[3].x(),
                                                   shapeFrom(in[4], in[5], &in[6]), in[7].x(), in[8].x()));
                          },
                          V));
  ops.push_back(weatherOp("weather_moss_coverage", "moss: least sun (eq. 3.5), low ground (eq. 3.9), noisy edges (eq. 3.14)",
                          {vec3Required("normal"), vec3Required("position"), vec3Required("diffuse"),
                           vec4Port("weights", kDefaultShape.weights), vec4Port("shape", kDefaultShapeVector),
                           floatRequired("noise")},
                          F, "wg_moss_coverage({normal}, {position}, {diffuse}, {weights}, {shape}, {noise})",
                          [](const Value* in, const EvalContext& c) {
                            return Value::scalar(mossCoverage(*c.frame, v3(in[0]), v3(in[1]), v3(in[2]),
                                                              shapeFrom(in[3], in[4], nullptr), in[5].x()));
                          },
                          V));
  ops.push_back(weatherOp("weather_puddle_coverage", "puddles on flat ground (section 5.1.2), shaped by the puddle noise",
                          {vec3Required("normal"), floatRequired("noise"), floatPort("exposure", 1.f, 0.f, 1.f)}, F,
                          "wg_puddle_coverage({normal}, {noise}, {exposure})", [](const Value* in, const EvalContext& c) {
                            return Value::scalar(puddleCoverage(*c.frame, v3(in[0]), in[1].x(), in[2].x()));
                          },
                          V));
  ops.push_back(weatherOp("weather_frost_coverage", "water freezing from the banks (eq. 3.20), noisy edges (eq. 3.14)",
                          {floatRequired("frostMap"), floatRequired("noise")}, F, "wg_frost_coverage({frostMap}, {noise})",
                          [](const Value* in, const EvalContext& c) {
                            return Value::scalar(frostCoverage(*c.frame, in[0].x(), in[1].x()));
                          },
                          V));
  ops.push_back(weatherOp("weather_puddle_ice", "how frozen standing water is: liquid only above 0 C, kept by the frost level",
                          {}, F, "wg_puddle_ice()",
                          [](const Value*, const EvalContext& c) { return Value::scalar(puddleIce(*c.frame)); }, V));
  ops.push_back(weatherOp("weather_hoarfrost_coverage", "frost crystals on exposed ground (eq. 3.14 edges)",
                          {floatRequired("noise"), floatPort("exposure", 1.f, 0.f, 1.f)}, F,
                          "wg_hoarfrost_coverage({noise}, {exposure})", [](const Value* in, const EvalContext& c) {
                            return Value::scalar(hoarfrostCoverage(*c.frame, in[0].x(), in[1].x()));
                          },
                          V));
}

}  // namespace wg
