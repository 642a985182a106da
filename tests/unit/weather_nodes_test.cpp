// The weather ops' CPU semantics (seed 000, chapter 3; docs/weather-model.md) against
// values computed by hand from the equations, called through the op registry the way
// constant folding and the CPU evaluator call them. The arithmetic is in the comments.
//
// Noise: the coverage ops take the shared noise lookup as an input, so most cases pass
// noise 0; wind and the ripple read the noise texture themselves, and their cases read
// the same texels through weather::sampleNoise (nodes/weather_noise.hpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "backends/shader_syntax.hpp"
#include "nodes/height_field.hpp"
#include "nodes/op_registry.hpp"
#include "nodes/texture_image.hpp"
#include "nodes/weather_maps.hpp"
#include "nodes/weather_noise.hpp"
#include "nodes/weather_shader_library.hpp"

namespace wg {
namespace {

struct Env {
  SurfacePoint surface;
  FrameState frame;
  const HeightField* terrainHeight = nullptr;
};

Value eval(std::string_view opName, std::vector<Value> inputs, const Env& env = {}) {
  const OpDef* op = findOp(opName);
  EXPECT_NE(op, nullptr) << opName;
  if (!op) return {};
  EXPECT_EQ(inputs.size(), op->inputs.size()) << opName << ": pass every input, defaults included";
  EvalContext context;
  context.surface = &env.surface;
  context.frame = &env.frame;
  context.terrainHeight = env.terrainHeight;
  return op->eval(inputs.data(), context);
}

void expectValue(const Value& actual, const Value& expected, float tolerance = 1e-5f) {
  ASSERT_EQ(actual.type, expected.type);
  for (int i = 0; i < expected.width(); ++i) EXPECT_NEAR(actual.v[i], expected.v[i], tolerance) << "component " << i;
}

Value s(float x) { return Value::scalar(x); }
Value v2(float x, float y) { return Value::vec2(x, y); }
Value v3(float x, float y, float z) { return Value::vec3(x, y, z); }
Value v4(float x, float y, float z, float w) { return Value::vec4(x, y, z, w); }

const Value kUp = v3(0, 1, 0);
const Value kDown = v3(0, -1, 0);
const Value kOrigin = v3(0, 0, 0);
const Value kWeights = v4(2, 0.5f, 2, 0.5f);   // defaults: w1 sun, w2 wind, w3 height, w4 terrain
const Value kShape = v4(-50, 50, 0.5f, 0);     // minHeight, maxHeight, inclination intensity
const Value kAllTerms = v4(1, 1, 1, 1);        // inclination, sun, height, wind switched on
// detailMask((0.5, 0.4, 0.2)) = 0.3*0.5 + 0.59*0.4 + 0.11*0.2 = 0.15 + 0.236 + 0.022 = 0.408
const Value kDiffuse = v3(0.5f, 0.4f, 0.2f);

TEST(WeatherNodes, EveryWeatherOpIsRegistered) {
  for (const char* name :
       {"weather_inclination", "weather_sun", "weather_wind", "weather_height", "weather_height_inverted",
        "weather_displacement", "terrain_coord", "terrain_height", "weather_terrain_slope", "weather_terrain_orientation",
        "weather_transition", "weather_prediction", "weather_wetness", "weather_wet_diffuse", "weather_wet_roughness",
        "weather_wet_normal", "weather_detail_mask", "weather_snow_albedo", "weather_moss_albedo", "weather_ice_albedo",
        "weather_frost_mask", "weather_puddle_mask", "tangent_to_world", "sky_exposure", "weather_levels",
        "weather_conditions", "weather_snow_coverage", "weather_snow_offset", "weather_moss_coverage",
        "weather_puddle_coverage", "weather_frost_coverage", "weather_hoarfrost_coverage", "weather_noise",
        "weather_noise_relief", "weather_specular_aa", "weather_wind_flow"}) {
    const OpDef* op = findOp(name);
    ASSERT_NE(op, nullptr) << name;
    EXPECT_NE(op->eval, nullptr) << name;
    EXPECT_EQ(op->category, "weather") << name;
  }
}

// Eq. 3.4: f_inc = Clamp(N.up + (Nd.up) * intensity)^3, Nd the normal-mapped world normal.
TEST(WeatherNodes, Inclination) {
  // Up-facing: Clamp(1 + 1 * 0.5) = 1 -> 1.
  expectValue(eval("weather_inclination", {kUp, kUp, s(0.5f)}), s(1));
  // Tilted (0.8, 0.6, 0), no bump: 0.6 + 0.6 * 0.5 = 0.9 -> 0.9^3 = 0.729.
  expectValue(eval("weather_inclination", {v3(0.8f, 0.6f, 0), v3(0.8f, 0.6f, 0), s(0.5f)}), s(0.729f));
  // Vertical face whose normal map bumps up to (0.6, 0.8, 0): 0 + 0.8 * 0.5 = 0.4 -> 0.064,
  // but the geometric gate Clamp(N.up / 0.1) = 0 keeps it bare.
  expectValue(eval("weather_inclination", {v3(1, 0, 0), v3(0.6f, 0.8f, 0), s(0.5f)}), s(0));
  // Nearly vertical, n = (0.99749, 0.05, 0): Clamp(0.05 + 0.8 * 0.5)^3 = 0.45^3 = 0.091125,
  // gate 0.05 / 0.1 = 0.5 -> 0.0455625.
  expectValue(eval("weather_inclination", {v3(0.99749f, 0.05f, 0), v3(0.6f, 0.8f, 0), s(0.5f)}), s(0.0455625f));
  // Downward: Clamp(-1 - 0.5) = 0.
  expectValue(eval("weather_inclination", {kDown, kDown, s(0.5f)}), s(0));
  // Intensity 0 ignores the normal map: 0.6^3 = 0.216.
  expectValue(eval("weather_inclination", {v3(0.8f, 0.6f, 0), kUp, s(0)}), s(0.216f));
}

// Eq. 3.5 for snow, relative to level ground:
// Clamp(1 - 1.5 Clamp(sunMelt) (max(N . L, 0) - max(up . L, 0))). The light's brightness
// (sunIntensity) plays no part.
TEST(WeatherNodes, SunFacing) {
  Env env;
  env.frame.sunDirection = {0, 1, 0};  // towards the sun: overhead
  env.frame.sunMelt = 0.8f;
  env.frame.sunIntensity = 0.f;  // the light is off; the melt strength still acts
  // Level ground: the reference, 1 under any sun.
  expectValue(eval("weather_sun", {kUp}, env), s(1));
  // Facing away or sideways: less sun than level ground -> 1 + ... -> 1.
  expectValue(eval("weather_sun", {kDown}, env), s(1));
  expectValue(eval("weather_sun", {v3(1, 0, 0)}, env), s(1));
  // A 30 degree sun, towards (cos 30, sin 30, 0), full strength. Level ground 1; the
  // sun-facing side (1, 0, 0): excess 0.8660254 - 0.5 = 0.3660254, 1 - 1.5 * 0.3660254 =
  // 0.4509619; a face turned straight at the sun: excess 0.5 -> 0.25.
  env.frame.sunDirection = {0.8660254f, 0.5f, 0};
  env.frame.sunMelt = 1.f;
  env.frame.sunIntensity = 1.f;
  expectValue(eval("weather_sun", {kUp}, env), s(1));
  expectValue(eval("weather_sun", {v3(1, 0, 0)}, env), s(0.4509619f));
  expectValue(eval("weather_sun", {v3(0.8660254f, 0.5f, 0)}, env), s(0.25f));
  // Melt strength clamps to 1, and 0 means no melt anywhere.
  env.frame.sunMelt = 2.f;
  expectValue(eval("weather_sun", {v3(0.8660254f, 0.5f, 0)}, env), s(0.25f));
  env.frame.sunMelt = 0.f;
  expectValue(eval("weather_sun", {v3(0.8660254f, 0.5f, 0)}, env), s(1));
}

// Eq. 3.6-3.7: f_wind(d) = f_pan(d.x, d.y) + 0.5 f_pan(d.y, d.x), f_pan(h, v) = the noise
// texture's flow channel (g) at xz / 32 + (h, v) * time / 8 (8 flow cells per 32 m tile);
// f_w = Clamp(N . (d.x, 0, d.y) * f_wind + windIntensity).
TEST(WeatherNodes, Wind) {
  using weather::sampleNoise;
  Env env;
  env.frame.windDirection = {1, 0};  // blowing towards +x
  env.frame.windIntensity = 0.2f;
  env.frame.time = 0;
  // At xz = (4, 8) and time 0 both phases read tile coordinates (0.125, 0.25).
  const float flow = 1.5f * sampleNoise({0.125f, 0.25f}).y;
  ASSERT_GT(flow, 0.f);
  // Leeward-tilted normal (0.6, 0.8, 0): 0.6 * flow + 0.2.
  expectValue(eval("weather_wind", {v3(0.6f, 0.8f, 0), v3(4, 0, 8)}, env), s(std::clamp(0.6f * flow + 0.2f, 0.f, 1.f)));
  // Windward (-0.6, 0.8, 0): -0.6 flow + intensity.
  env.frame.windIntensity = 1.f;
  expectValue(eval("weather_wind", {v3(-0.6f, 0.8f, 0), v3(4, 0, 8)}, env), s(std::clamp(1.f - 0.6f * flow, 0.f, 1.f)));
  // Up-facing: N . (1, 0, 0) = 0 -> Clamp(windIntensity) = 1.
  expectValue(eval("weather_wind", {kUp, v3(4, 0, 8)}, env), s(1));
  // Panning: at xz = (0, 0), time 4, the phases read (4, 0) / 8 = (0.5, 0) and (0, 0.5).
  env.frame.windIntensity = 0.f;
  env.frame.time = 4.f;
  const float panned = sampleNoise({0.5f, 0.f}).y + 0.5f * sampleNoise({0.f, 0.5f}).y;
  expectValue(eval("weather_wind", {v3(0.6f, 0.8f, 0), kOrigin}, env), s(std::clamp(0.6f * panned, 0.f, 1.f)));
  // Wind towards +z acts on z-facing sides; the phases swap.
  env.frame.windDirection = {0, 1};
  const float swapped = sampleNoise({0.f, 0.5f}).y + 0.5f * sampleNoise({0.5f, 0.f}).y;
  expectValue(eval("weather_wind", {v3(0, 0.8f, 0.6f), kOrigin}, env), s(std::clamp(0.6f * swapped, 0.f, 1.f)));
}

// Eq. 3.8-3.9: Clamp((y - min) / (max - min)) and 1 - that.
TEST(WeatherNodes, HeightAndInvertedHeight) {
  expectValue(eval("weather_height", {v3(7, 0, 3), s(-50), s(50)}), s(0.5f));    // 50 / 100
  expectValue(eval("weather_height", {v3(0, 25, 0), s(-50), s(50)}), s(0.75f));  // 75 / 100
  expectValue(eval("weather_height", {v3(0, 100, 0), s(-50), s(50)}), s(1));     // 1.5 -> 1
  expectValue(eval("weather_height", {v3(0, -60, 0), s(-50), s(50)}), s(0));     // -0.1 -> 0
  // A degenerate range divides by 1e-3 m instead of 0: 0.0005 / 0.001 = 0.5.
  expectValue(eval("weather_height", {v3(0, 0.0005f, 0), s(0), s(0)}), s(0.5f), 1e-3f);
  expectValue(eval("weather_height_inverted", {v3(0, 25, 0), s(-50), s(50)}), s(0.25f));  // 1 - 0.75
  expectValue(eval("weather_height_inverted", {v3(0, -60, 0), s(-50), s(50)}), s(1));
}

// Eq. 3.10: (Clamp(noise + 0.75) * progress * maxSnowHeight) * N.
TEST(WeatherNodes, Displacement) {
  // Clamp(0.1 + 0.75) = 0.85; 0.85 * 0.5 * 0.25 = 0.10625 along up.
  expectValue(eval("weather_displacement", {s(0.1f), s(0.5f), s(0.25f), kUp}), v3(0, 0.10625f, 0));
  // Clamp(0.5 + 0.75) = 1; 1 * 1 * 0.25 = 0.25 along (0.6, 0.8, 0) -> (0.15, 0.2, 0).
  expectValue(eval("weather_displacement", {s(0.5f), s(1), s(0.25f), v3(0.6f, 0.8f, 0)}), v3(0.15f, 0.2f, 0));
  // No progress, no offset.
  expectValue(eval("weather_displacement", {s(0.5f), s(0), s(0.25f), kUp}), v3(0, 0, 0));
}

// Eq. 3.11: (world xz - region origin) * (1 / region size).
TEST(WeatherNodes, TerrainCoord) {
  Env env;
  env.frame.terrainRegion = {10, -20, 0.01f, 0.02f};
  // ((60 - 10) * 0.01, (30 + 20) * 0.02) = (0.5, 1.0); y does not matter.
  expectValue(eval("terrain_coord", {v3(60, 5, 30)}, env), v2(0.5f, 1.0f));
  expectValue(eval("terrain_coord", {v3(10, -99, -20)}, env), v2(0, 0));
}

// The shared height map: float heights, linear filtering, clamp to edge; 0 without a map.
TEST(WeatherNodes, TerrainHeight) {
  Env env;
  expectValue(eval("terrain_height", {v2(0.3f, 0.7f)}, env), s(0));
  // A 2 x 2 map whose columns hold 0 and 1: texel centres at u = 0.25 and 0.75.
  HeightField map{2, {0.f, 1.f, 0.f, 1.f}};
  env.terrainHeight = &map;
  expectValue(eval("terrain_height", {v2(0.25f, 0.5f)}, env), s(0));    // on texel 0
  expectValue(eval("terrain_height", {v2(0.5f, 0.5f)}, env), s(0.5f));  // halfway: (0 + 1) / 2
  expectValue(eval("terrain_height", {v2(0.75f, 0.5f)}, env), s(1));    // on texel 1
  expectValue(eval("terrain_height", {v2(2.0f, 0.5f)}, env), s(1));     // clamped to the edge
}

// Eq. 3.12: (1, 0, I (hU - h0)) x (0, 1, I (hV - h0)).
TEST(WeatherNodes, TerrainSlope) {
  // a = (1, 0, 10 * 0.1) = (1, 0, 1), b = (0, 1, 10 * -0.1) = (0, 1, -1):
  // a x b = (0 * -1 - 1 * 1, 1 * 0 - 1 * -1, 1 * 1 - 0 * 0) = (-1, 1, 1).
  expectValue(eval("weather_terrain_slope", {s(0.2f), s(0.3f), s(0.1f), s(10)}), v3(-1, 1, 1));
  // Flat: (1, 0, 0) x (0, 1, 0) = (0, 0, 1).
  expectValue(eval("weather_terrain_slope", {s(0.4f), s(0.4f), s(0.4f), s(10)}), v3(0, 0, 1));
}

// Eq. 3.13: ((slope * (1, 1, 0)) . N) (TN . (0, 0, 1)) intensity, slope (u, v) -> world (x, z).
TEST(WeatherNodes, TerrainOrientation) {
  // Horizontal slope (-1, 0, 1) in world; N = (-0.6, 0, 0.8): 0.6 + 0.8 = 1.4; * 0.5 * 2 = 1.4.
  expectValue(eval("weather_terrain_orientation", {v3(-1, 1, 1), v3(-0.6f, 0, 0.8f), s(0.5f), s(2)}), s(1.4f));
  // Up-facing surfaces are unaffected: (-1, 0, 1) . (0, 1, 0) = 0.
  expectValue(eval("weather_terrain_orientation", {v3(-1, 1, 1), kUp, s(1), s(1)}), s(0));
  // A negative intensity flips the side: 1.4 * 0.5 * -2 = -1.4 (not clamped here).
  expectValue(eval("weather_terrain_orientation", {v3(-1, 1, 1), v3(-0.6f, 0, 0.8f), s(0.5f), s(-2)}), s(-1.4f));
}

// Eq. 3.14: Clamp(noise - 1 + 3 p).
TEST(WeatherNodes, Transition) {
  expectValue(eval("weather_transition", {s(0.4f), s(0.3f)}), s(0.3f));  // 0.4 - 1 + 0.9
  expectValue(eval("weather_transition", {s(0.4f), s(0)}), s(0));        // -0.6 -> 0
  expectValue(eval("weather_transition", {s(0.4f), s(1)}), s(1));        // 2.4 -> 1
  expectValue(eval("weather_transition", {s(0), s(1.0f / 3.0f)}), s(0)); // the last spot fills at p = 2/3
  expectValue(eval("weather_transition", {s(0), s(2.0f / 3.0f)}), s(1));
}

// Eq. 3.1 as read: Clamp(inc * (w1 sun * w3 height + w4 terrain + w2 wind)).
TEST(WeatherNodes, Prediction) {
  // 2*0.5*2*0.5 = 1.0; + 0.5*0.2 = 0.1; + 0.5*0.4 = 0.2 -> 1.3; * 0.729 = 0.9477.
  expectValue(eval("weather_prediction", {s(0.729f), s(0.5f), s(0.5f), s(0.2f), s(0.4f), kWeights}), s(0.9477f));
  // Inclination gates wind and terrain: nothing on a downward face (f_inc = 0).
  expectValue(eval("weather_prediction", {s(0), s(1), s(1), s(1), s(1), kWeights}), s(0));
  // The default weights' design point: up-facing (inc 1), mid height (0.5), 30 degree sun
  // (sun 0.5), no wind or terrain: 2 * 0.5 * 2 * 0.5 = 1 -> fully covered.
  expectValue(eval("weather_prediction", {s(1), s(0.5f), s(0.5f), s(0), s(0), kWeights}), s(1));
  // Clamped above: 1 * (2 * 1 * 2 * 1) = 4 -> 1.
  expectValue(eval("weather_prediction", {s(1), s(1), s(1), s(0), s(0), kWeights}), s(1));
  // Other weights: inc 0.5 * (1 * 0.4 * 1 * 0.5 + 2 * 0.1 + 0 * wind) = 0.5 * 0.4 = 0.2.
  expectValue(eval("weather_prediction", {s(0.5f), s(0.4f), s(0.5f), s(0.1f), s(0.9f), v4(1, 0, 1, 2)}), s(0.2f));
}

// Eq. 3.15 as read: wetnessLevel * Clamp(exposure) * smoothstep(0, 1 C, T).
TEST(WeatherNodes, Wetness) {
  Env env;
  env.frame.wetnessLevel = 0.6f;
  env.frame.temperature = 10;
  expectValue(eval("weather_wetness", {s(1)}, env), s(0.6f));
  expectValue(eval("weather_wetness", {s(0.5f)}, env), s(0.3f));  // sheltered half
  env.frame.temperature = 0.5f;                                      // smoothstep = 0.25 * 2 = 0.5
  expectValue(eval("weather_wetness", {s(1)}, env), s(0.3f));
  env.frame.temperature = 0.25f;  // 0.0625 * (3 - 0.5) = 0.15625; * 0.6 = 0.09375
  expectValue(eval("weather_wetness", {s(1)}, env), s(0.09375f));
  env.frame.temperature = -2;  // frozen: no liquid water
  expectValue(eval("weather_wetness", {s(1)}, env), s(0));
  env.frame.temperature = 10;
  env.frame.wetnessLevel = 0;  // dry, even in rain: the level is what the shader reads
  env.frame.precipitation = 1;
  expectValue(eval("weather_wetness", {s(1)}, env), s(0));
}

// Eq. 3.16-3.17.
TEST(WeatherNodes, WetDiffuseAndRoughness) {
  // Lerp(1, 0.7, 0.5) = 0.85: (0.5, 0.4, 0.2) * 0.85 = (0.425, 0.34, 0.17).
  expectValue(eval("weather_wet_diffuse", {kDiffuse, s(0.5f), s(0)}), v3(0.425f, 0.34f, 0.17f));
  // Fully wet: 70 %.
  expectValue(eval("weather_wet_diffuse", {v3(1, 0.5f, 0), s(1), s(0)}), v3(0.7f, 0.35f, 0));
  expectValue(eval("weather_wet_diffuse", {kDiffuse, s(0), s(0)}), kDiffuse);
  expectValue(eval("weather_wet_roughness", {s(0.8f), s(0.3f), s(0)}), s(0.5f));  // 0.8 - 0.3
  expectValue(eval("weather_wet_roughness", {s(0.2f), s(0.5f), s(0)}), s(0));     // -0.3 -> 0
  // By porosity: a metal does not darken, and keeps min(R, 0.15) of its roughness.
  expectValue(eval("weather_wet_diffuse", {kDiffuse, s(1), s(1)}), kDiffuse);
  expectValue(eval("weather_wet_diffuse", {v3(1, 0.5f, 0), s(1), s(0.5f)}), v3(0.85f, 0.425f, 0));
  expectValue(eval("weather_wet_roughness", {s(0.8f), s(1), s(1)}), s(0.15f));
  expectValue(eval("weather_wet_roughness", {s(0.1f), s(1), s(1)}), s(0.1f));
}

// A point has no footprint: the CPU's specular anti-aliasing keeps the roughness,
// whatever the normal. The lit frame widens it from the normal's pixel derivatives.
TEST(WeatherNodes, SpecularAntiAliasingKeepsAPointsRoughness) {
  expectValue(eval("weather_specular_aa", {s(0.5f), v3(0, 0, 1)}), s(0.5f));
  expectValue(eval("weather_specular_aa", {s(0.05f), v3(0.3f, 0, 0.95f)}), s(0.05f));
  const OpDef* op = findOp("weather_specular_aa");
  ASSERT_NE(op, nullptr);
  EXPECT_NE(op->glsl.find("dFdx({normal})"), std::string::npos);
  EXPECT_NE(op->glsl.find("dFdy({normal})"), std::string::npos);
}

// Eq. 3.18 as read: N + pan * 2 * 0.25 * rain with one lookup n of the noise texture's
// ripple channel (b) at xz / 32 + (0.5, 0.01) * p * time / 64 (64 ripple cells per tile)
// giving both slopes, pan = (n.b - 0.5, n.r - 0.5), and rain = smoothstep(0, 0.1,
// precipitation).
TEST(WeatherNodes, WetNormal) {
  Env env;
  const Value flat = v3(0, 0, 1);
  // No rain: unchanged, however wet.
  env.frame.precipitation = 0;
  expectValue(eval("weather_wet_normal", {flat, kOrigin, s(1)}, env), flat);
  // Rain but p = 0: unchanged.
  env.frame.precipitation = 1;
  expectValue(eval("weather_wet_normal", {flat, kOrigin, s(0)}, env), flat);
  // Precipitation 0.05 -> rain = smoothstep(0, 0.1, 0.05) = 0.5; scale 2 * 0.25 * 0.5 = 0.25.
  // At xz = 0, time 0 the lookup is at (0, 0).
  env.frame.precipitation = 0.05f;
  const glm::vec4 n0 = weather::sampleNoise({0.f, 0.f});
  expectValue(eval("weather_wet_normal", {flat, kOrigin, s(1)}, env),
              v3(0.25f * (n0.z - 0.5f), 0.25f * (n0.x - 0.5f), 1), 1e-4f);
  // Full rain (scale 0.5), p = 0.5, time 4: uv = (0.5, 0.01) * 0.5 * 4 / 64 = (0.015625, 0.0003125).
  env.frame.precipitation = 1;
  env.frame.time = 4;
  glm::vec4 n = weather::sampleNoise({0.015625f, 0.0003125f});
  float px = n.z - 0.5f, py = n.x - 0.5f;  // the ripple and transition channels
  expectValue(eval("weather_wet_normal", {v3(0.1f, 0.2f, 0.9f), kOrigin, s(0.5f)}, env),
              v3(0.1f + px * 0.5f, 0.2f + py * 0.5f, 0.9f), 1e-4f);
}

// A layer's relief (snow's amplitude): the transition noise as a 25 cm height field, sloped by forward
// differences 12.5 cm along x and z, in the tangent frame. On level ground with the
// tangent along +x the bitangent is -z, so the normal leans against the slope in x and
// with it in z.
TEST(WeatherNodes, NoiseReliefIsTheNoiseHeightsNormalInTangentSpace) {
  Env env;
  env.surface.worldNormal = {0.f, 1.f, 0.f};
  env.surface.tangent = {1.f, 0.f, 0.f, 1.f};
  const glm::vec3 p(3.f, 0.f, 5.f);
  float h = weather::noiseAt(p).x;
  float hx = weather::noiseAt(p + glm::vec3(0.125f, 0.f, 0.f)).x, hz = weather::noiseAt(p + glm::vec3(0.f, 0.f, 0.125f)).x;
  expectValue(eval("weather_noise_relief", {v3(p.x, p.y, p.z), s(h), s(0.25f)}, env), v3(-2.f * (hx - h), 2.f * (hz - h), 1.f),
              1e-5f);
}

// Eq. 3.19 with p = 1: Clamp((0.3, 0.59, 0.11) . diffuse).
TEST(WeatherNodes, DetailMask) {
  expectValue(eval("weather_detail_mask", {kDiffuse}), s(0.408f));
  expectValue(eval("weather_detail_mask", {v3(1, 1, 1)}), s(1));  // 0.3 + 0.59 + 0.11
  expectValue(eval("weather_detail_mask", {v3(2, 2, 2)}), s(1));  // clamped
  expectValue(eval("weather_detail_mask", {v3(1, 0, 0)}), s(0.3f));
}

float reflectance(const Value& c) { return 0.3f * c.v[0] + 0.59f * c.v[1] + 0.11f * c.v[2]; }

// Eq. 3.19 + Table 4.1: value = Lerp(low, high, Clamp(mask * spread)); albedo = tint /
// reflectance(tint) * value, so the reflectance of the result is exactly the value.
TEST(WeatherNodes, SnowMossIceAlbedo) {
  // Snow, spread 2: 0.408 * 2 = 0.816; 0.9 + 0.05 * 0.816 = 0.9408. Tint (0.97, 0.985, 1),
  // reflectance 0.291 + 0.58115 + 0.11 = 0.98215: (0.9291615, 0.9435300, 0.9578985).
  expectValue(eval("weather_snow_albedo", {kDiffuse}), v3(0.9291615f, 0.9435300f, 0.9578985f));
  EXPECT_NEAR(reflectance(eval("weather_snow_albedo", {kDiffuse})), 0.9408f, 1e-5f);
  EXPECT_NEAR(reflectance(eval("weather_snow_albedo", {v3(0, 0, 0)})), 0.90f, 1e-5f);  // black: band low
  EXPECT_NEAR(reflectance(eval("weather_snow_albedo", {v3(1, 1, 1)})), 0.95f, 1e-5f);  // white: band high
  // Moss, spread 1.5: 0.408 * 1.5 = 0.612; 0.25 + 0.28 * 0.612 = 0.42136. Tint (0.45, 0.75, 0.2),
  // reflectance 0.135 + 0.4425 + 0.022 = 0.5995: (0.3162836, 0.5271393, 0.1405705).
  expectValue(eval("weather_moss_albedo", {kDiffuse}), v3(0.3162836f, 0.5271393f, 0.1405705f));
  EXPECT_NEAR(reflectance(eval("weather_moss_albedo", {v3(0, 0, 0)})), 0.25f, 1e-5f);
  EXPECT_NEAR(reflectance(eval("weather_moss_albedo", {v3(1, 1, 1)})), 0.53f, 1e-5f);
  // Ice, spread 3: 0.408 * 3 = 1.224 -> 1 -> 0.7. Tint (0.85, 0.95, 1), reflectance
  // 0.255 + 0.5605 + 0.11 = 0.9255: (0.6428957, 0.7185305, 0.7563479).
  expectValue(eval("weather_ice_albedo", {kDiffuse, v3(0, 0, 1)}), v3(0.6428957f, 0.7185305f, 0.7563479f));
  // Dark grey 0.1: 0.1 * 3 = 0.3; 0.5 + 0.2 * 0.3 = 0.56.
  EXPECT_NEAR(reflectance(eval("weather_ice_albedo", {v3(0.1f, 0.1f, 0.1f), v3(0, 0, 1)})), 0.56f, 1e-5f);
  EXPECT_NEAR(reflectance(eval("weather_ice_albedo", {v3(0, 0, 0), v3(0, 0, 1)})), 0.5f, 1e-5f);
  // Cracks: a bend of the frozen surface's normal (|xy| 0.6 or more) goes to the band's
  // top; half way (|xy| 0.45, smoothstep 0.5) adds 0.5 to the mask: 0.3 + 0.5 -> 0.66.
  EXPECT_NEAR(reflectance(eval("weather_ice_albedo", {v3(0, 0, 0), v3(0.7f, 0, 0.7f)})), 0.7f, 1e-5f);
  EXPECT_NEAR(reflectance(eval("weather_ice_albedo", {v3(0.1f, 0.1f, 0.1f), v3(0, 0.45f, 0.9f)})), 0.66f, 1e-5f);
  // Whatever the input, the result stays in the measured band.
  for (float g : {0.f, 0.05f, 0.2f, 0.5f, 0.9f, 1.f, 3.f}) {
    float snow = reflectance(eval("weather_snow_albedo", {v3(g, g, g)}));
    float moss = reflectance(eval("weather_moss_albedo", {v3(g, g, g)}));
    float ice = reflectance(eval("weather_ice_albedo", {v3(g, g, g), v3(0, 0, 1)}));
    EXPECT_TRUE(snow >= 0.9f - 1e-5f && snow <= 0.95f + 1e-5f) << g << ": " << snow;
    EXPECT_TRUE(moss >= 0.25f - 1e-5f && moss <= 0.53f + 1e-5f) << g << ": " << moss;
    EXPECT_TRUE(ice >= 0.5f - 1e-5f && ice <= 0.7f + 1e-5f) << g << ": " << ice;
  }
}

// Eq. 3.20 as read: (1 - F)^Lerp(0, 5, 1 - frost) * Clamp(10 frost).
TEST(WeatherNodes, FrostMask) {
  // F = 0.5, frost 0.5: exponent 2.5, 0.5^2.5 = 0.1767767; fade Clamp(5) = 1.
  expectValue(eval("weather_frost_mask", {s(0.5f), s(0.5f)}), s(0.1767767f));
  // Fully frozen: exponent 0 -> 1 everywhere, mid-stream too (base max(0, 1e-4)^0 = 1).
  expectValue(eval("weather_frost_mask", {s(0.5f), s(1)}), s(1));
  expectValue(eval("weather_frost_mask", {s(1), s(1)}), s(1));
  // Liquid: the fade-in is 0, so even the banks (F = 0, base 1) have no ice.
  expectValue(eval("weather_frost_mask", {s(0), s(0)}), s(0));
  // Freezing starts at the banks: frost 0.05 -> exponent 4.75, fade 0.5: bank 1^4.75 * 0.5 = 0.5,
  // mid-stream (1e-4)^4.75 * 0.5 ~ 0.
  expectValue(eval("weather_frost_mask", {s(0), s(0.05f)}), s(0.5f));
  expectValue(eval("weather_frost_mask", {s(1), s(0.05f)}), s(0));
  // Half way across (F = 0.5) at frost 0.8: 0.5^1 = 0.5.
  expectValue(eval("weather_frost_mask", {s(0.5f), s(0.8f)}), s(0.5f));
}

// Section 5.1.2: smoothstep(cos 8, cos 4, N.up) * smoothstep(0.45, 0.55, noise + level - 0.5).
TEST(WeatherNodes, PuddleMask) {
  // Flat, noise 0.5, level 0.5: 0.5 -> smoothstep = 0.5.
  expectValue(eval("weather_puddle_mask", {kUp, s(0.5f), s(0.5f)}), s(0.5f));
  expectValue(eval("weather_puddle_mask", {kUp, s(0.3f), s(0.5f)}), s(0));  // 0.3 < 0.45
  expectValue(eval("weather_puddle_mask", {kUp, s(0.3f), s(0.9f)}), s(1));  // 0.7 > 0.55
  // Tilted 10 degrees: cos 10 = 0.9848 < cos 8 = 0.9902681 -> 0.
  const float d = 3.14159265f / 180.f;
  expectValue(eval("weather_puddle_mask", {v3(std::sin(10 * d), std::cos(10 * d), 0), s(0.3f), s(0.9f)}), s(0));
  // Tilted 6 degrees: t = (0.9945219 - 0.9902681) / (0.9975641 - 0.9902681) = 0.5830369;
  // t^2 (3 - 2t) = 0.6234103.
  expectValue(eval("weather_puddle_mask", {v3(std::sin(6 * d), std::cos(6 * d), 0), s(0.3f), s(0.9f)}), s(0.6234103f),
              2e-4f);
}

// Tangent space -> world with the surface's orthonormal frame (b = cross(n, t) * w).
TEST(WeatherNodes, TangentToWorld) {
  Env env;
  env.surface.worldNormal = {0, 1, 0};
  env.surface.tangent = {1, 0, 0, 1};  // b = (0, 1, 0) x (1, 0, 0) = (0, 0, -1)
  expectValue(eval("tangent_to_world", {v3(0, 0, 1)}, env), v3(0, 1, 0));
  expectValue(eval("tangent_to_world", {v3(1, 0, 0)}, env), v3(1, 0, 0));
  expectValue(eval("tangent_to_world", {v3(0, 1, 0)}, env), v3(0, 0, -1));
  expectValue(eval("tangent_to_world", {v3(0.6f, 0, 0.8f)}, env), v3(0.6f, 0.8f, 0));
  expectValue(eval("tangent_to_world", {v3(0, 0, 2)}, env), v3(0, 1, 0));  // normalised
  env.surface.tangent = {1, 0, 0, -1};  // mirrored: b = (0, 0, 1)
  expectValue(eval("tangent_to_world", {v3(0, 1, 0)}, env), v3(0, 0, 1));
  env.surface.tangent = {1, 1, 0, 1};  // not orthogonal: Gram-Schmidt gives (1, 0, 0)
  expectValue(eval("tangent_to_world", {v3(1, 0, 0)}, env), v3(1, 0, 0));
}

TEST(WeatherNodes, SkyExposureLevelsAndConditions) {
  Env env;
  env.surface.skyExposure = 0.25f;
  expectValue(eval("sky_exposure", {v3(1, 2, 3)}, env), s(0.25f));
  env.frame.snowLevel = 0.1f;
  env.frame.wetnessLevel = 0.2f;
  env.frame.mossLevel = 0.3f;
  env.frame.frostLevel = 0.4f;
  env.frame.temperature = -3;
  env.frame.precipitation = 0.7f;
  env.frame.windIntensity = 0.8f;
  env.frame.sunIntensity = 0.9f;
  Value levels = eval("weather_levels", {}, env);
  expectValue(levels, v4(0.1f, 0.2f, 0.3f, 0.4f));
  const OpDef* op = findOp("weather_levels");
  expectValue(applyAccessor(levels, op->outputs[static_cast<std::size_t>(op->findOutput("moss"))].accessor), s(0.3f));
  Value conditions = eval("weather_conditions", {}, env);
  expectValue(conditions, v4(-3, 0.7f, 0.8f, 0.9f));
  op = findOp("weather_conditions");
  expectValue(applyAccessor(conditions, op->outputs[static_cast<std::size_t>(op->findOutput("precipitation"))].accessor),
              s(0.7f));
}

// Snow: transition(0.5 noise + 0.5 (1 - detailMask), f_p * snowLevel * exposure), noise the
// shared lookup's transition channel, an input. With noise 0 the transition noise is
// 0.5 * (1 - 0.408) = 0.296.
TEST(WeatherNodes, SnowCoverage) {
  Env env;
  env.frame.temperature = -5;  // settling snow: eq. 3.14 as printed (melting: below)
  auto coverage = [&](const Value& n, const Value& nd, float exposure, const Value& terms = kAllTerms,
                      const Value& position = kOrigin, float terrain = 0, float windFlow = 0) {
    return eval("weather_snow_coverage",
                {n, nd, position, kDiffuse, s(terrain), s(windFlow), s(exposure), kWeights, kShape, terms, s(0), s(0.5f), s(0)},
                env);
  };
  // Level 0: the early-out, however favourable everything else is.
  env.frame.snowLevel = 0;
  expectValue(coverage(kUp, kUp, 1, kAllTerms, kOrigin, 1), s(0));
  // Full level: inc 1, sun 1 (no sun), height 0.5, wind Clamp(0 + 0) = 0, terrain 0:
  // f_p = Clamp(1 * 2 * 1 * 2 * 0.5) = 1; transition(0.296, 1) = Clamp(0.296 + 2) = 1.
  env.frame.snowLevel = 1;
  expectValue(coverage(kUp, kUp, 1), s(1));
  // Fully sheltered: level * exposure = 0 -> 0.
  expectValue(coverage(kUp, kUp, 0), s(0));
  // Half exposed: transition(0.296, 0.5) = 0.296 - 1 + 1.5 = 0.796.
  expectValue(coverage(kUp, kUp, 0.5f), s(0.796f));
  // Snow level 0.3: 0.296 - 1 + 0.9 = 0.196.
  env.frame.snowLevel = 0.3f;
  expectValue(coverage(kUp, kUp, 1), s(0.196f));
  // Downward faces get nothing, even with full wind and terrain terms (inclination gates them).
  env.frame.snowLevel = 1;
  env.frame.windIntensity = 1;
  expectValue(coverage(kDown, kDown, 1, kAllTerms, kOrigin, 1), s(0));
  env.frame.windIntensity = 0;
  // ...unless inclination is switched off (terms.x = 0): f_p = Clamp(2 * 1 * 2 * 0.5) = 1 -> 1.
  expectValue(coverage(kDown, kDown, 1, v4(0, 1, 1, 1)), s(1));
  // Sun from the +x horizon at full melt strength, snow level 0.3. Sun-facing (0.6, 0.8,
  // 0): inc Clamp(0.8 + 0.4) = 1, sun Clamp(1 - 1.5 * 0.6) = 0.1, f_p = 2 * 0.1 * 2 * 0.5 =
  // 0.2; transition(0.296, 0.06) = 0.296 - 1 + 0.18 < 0 -> 0. The shaded side (-0.6, 0.8,
  // 0): sun 1, f_p 1 -> 0.196.
  env.frame.sunDirection = {1, 0, 0};
  env.frame.sunMelt = 1;
  env.frame.snowLevel = 0.3f;
  expectValue(coverage(v3(0.6f, 0.8f, 0), v3(0.6f, 0.8f, 0), 1), s(0));
  expectValue(coverage(v3(-0.6f, 0.8f, 0), v3(-0.6f, 0.8f, 0), 1), s(0.196f));
  // Switching the sun off (terms.y = 0) makes both sides alike.
  expectValue(coverage(v3(0.6f, 0.8f, 0), v3(0.6f, 0.8f, 0), 1, v4(1, 0, 1, 1)), s(0.196f));
  // The wind term reads the flow it is given (eq. 3.7): wind towards +x, flow 1, a face
  // (0.6, 0.8, 0) 40 m down the snow line (height 0.1) with the sun off: inc 1, wind
  // Clamp(0.6 * 1) = 0.6, f_p = 1 * 2 * 0.1 + 0.5 * 0.6 = 0.5 -> transition(0.296, 0.5) =
  // 0.796; without flow f_p = 0.2 -> 0.296 - 1 + 0.6 < 0 -> 0.
  env.frame.snowLevel = 1;
  env.frame.windDirection = {1, 0};
  const Value leeward = v3(0.6f, 0.8f, 0);
  const Value low = v3(0, -40, 0);
  expectValue(coverage(leeward, leeward, 1, v4(1, 0, 1, 1), low, 0, 1.f), s(0.796f));
  expectValue(coverage(leeward, leeward, 1, v4(1, 0, 1, 1), low, 0, 0.f), s(0));
  // With the wind term off the flow is never read.
  expectValue(coverage(leeward, leeward, 1, v4(1, 0, 1, 0), low, 0, 1.f), s(0));
}

// Melting snow (above 0 C) in patches: the shape lerp(noise, patchNoise, 0.8) stretched
// about 0.5 by 2.3, eq. 3.14 of it at p = f_p * level, smoothstep(0.35, 0.65, that).
// Level up, no sun or wind, height 0.5: f_p = 1 as above; noise 0.
TEST(WeatherNodes, MeltingSnowCoversInPatches) {
  Env env;
  env.frame.temperature = 6;
  auto coverage = [&](float level, float patchNoise) {
    env.frame.snowLevel = level;
    return eval("weather_snow_coverage", {kUp, kUp, kOrigin, kDiffuse, s(0), s(0), s(1), kWeights, kShape, kAllTerms, s(0),
                                          s(patchNoise), s(1)},
                env);
  };
  // patchNoise 0.5: shape 0.4, stretched 0.27. Level 0.3: 0.27 - 1 + 0.9 = 0.17 -> bare;
  // level 0.5: 0.77 -> covered.
  expectValue(coverage(0.3f, 0.5f), s(0));
  expectValue(coverage(0.5f, 0.5f), s(1));
  // patchNoise 1: stretched 1. Level 0.3 -> 0.9, covered; level 0.2 -> 0.6, on the soft
  // edge: t = 0.25 / 0.3, t^2 (3 - 2t) = 0.925926.
  expectValue(coverage(0.3f, 1), s(1));
  expectValue(coverage(0.2f, 1), s(0.925926f));
  expectValue(coverage(0, 1), s(0));  // level 0 is bare wherever the patch lies
  // At 0.5 C half melting (smoothstep(0, 1 C, T)): half the settling cover (0.196 at
  // level 0.3, see above), half the patch (1).
  env.frame.temperature = 0.5f;
  expectValue(coverage(0.3f, 1), s(0.598f));
}

// Eq. 3.6 alone: weather_wind_flow is the f_wind that weather_wind's eq. 3.7 uses, so the
// injected snow (flow per vertex, eq. 3.7 per pixel) matches weather_wind at a point.
TEST(WeatherNodes, WindFlowIsTheFlowOfTheWindTerm) {
  using weather::sampleNoise;
  Env env;
  env.frame.windDirection = {0.8f, 0.6f};
  env.frame.windIntensity = 0.1f;
  env.frame.time = 3.f;
  const Value p = v3(5, 2, -7);
  // xz / 32 + d * time / 8, and the swapped phase at half weight.
  glm::vec2 uv(5.f / 32.f, -7.f / 32.f);
  glm::vec2 pan = glm::vec2(0.8f, 0.6f) * (3.f / 8.f);
  float flow = sampleNoise(uv + pan).y + 0.5f * sampleNoise(uv + glm::vec2(pan.y, pan.x)).y;
  expectValue(eval("weather_wind_flow", {p}, env), s(flow));
  const OpDef* op = findOp("weather_wind_flow");
  ASSERT_NE(op, nullptr);
  EXPECT_EQ(op->rate, OpRate::Vertex);
  const Value n = v3(0.48f, 0.6f, 0.64f);
  expectValue(eval("weather_wind", {n, p}, env), s(std::clamp((0.48f * 0.8f + 0.64f * 0.6f) * flow + 0.1f, 0.f, 1.f)));
}

// Snow offset (vertex stage): eq. 3.10 with f_p (detail normal = geometric normal, no
// terrain) * snowLevel * exposure and the coverage noise.
TEST(WeatherNodes, SnowOffset) {
  Env env;
  auto offset = [&](const Value& n, float exposure, float maxSnowHeight) {
    return eval("weather_snow_offset", {n, kOrigin, s(0), s(exposure), kWeights, kShape, kAllTerms, s(maxSnowHeight), s(0)},
                env);
  };
  env.frame.snowLevel = 0;
  expectValue(offset(kUp, 1, 0.25f), v3(0, 0, 0));
  // Full: f_p = 1 (as above), noise 0: Clamp(0 + 0.75) * 1 * 0.25 = 0.1875 along up.
  env.frame.snowLevel = 1;
  expectValue(offset(kUp, 1, 0.25f), v3(0, 0.1875f, 0));
  // Half the level (or half exposure): 0.09375; a 1 m max height: 0.75.
  expectValue(offset(kUp, 0.5f, 0.25f), v3(0, 0.09375f, 0));
  expectValue(offset(kUp, 1, 1), v3(0, 0.75f, 0));
  expectValue(offset(kDown, 1, 0.25f), v3(0, 0, 0));  // f_p = 0 on downward faces
}

// Moss: transition(0.5 noise + 0.5 (1 - detailMask), Clamp(w1 shade w3 (1 - height)) *
// Clamp(1 + 2 N.up) * mossLevel), shade = Clamp(0.5 - 0.5 sunMelt N.L) (eq. 3.5 for moss).
// The noise is the same shared transition noise as snow's (eq. 3.14); with noise 0 the
// transition noise is again 0.296.
TEST(WeatherNodes, MossCoverage) {
  Env env;
  const Value at = v3(-17.3f, 0, -9.1f);
  auto coverage = [&](const Value& n, const Value& position) {
    return eval("weather_moss_coverage", {n, position, kDiffuse, kWeights, kShape, s(0)}, env);
  };
  env.frame.mossLevel = 0;
  expectValue(coverage(kUp, at), s(0));
  // Full level, up-facing, y = 0, no melt: shade 0.5, low 0.5, facing 1:
  // Clamp(2 * 0.5 * 2 * 0.5) * 1 = 1 -> 1.
  env.frame.mossLevel = 1;
  expectValue(coverage(kUp, at), s(1));
  // Level 0.3: 0.296 - 1 + 0.9 = 0.196; sides alike (facing Clamp(1 + 0) = 1).
  env.frame.mossLevel = 0.3f;
  expectValue(coverage(kUp, at), s(0.196f));
  expectValue(coverage(v3(1, 0, 0), at), s(0.196f));
  env.frame.mossLevel = 1;
  // Overhangs: facing Clamp(1 - 2) = 0 -> transition(0.296, 0) = 0.
  expectValue(coverage(kDown, at), s(0));
  // High ground (y = 50 = maxHeight): low = 0 -> 0.
  expectValue(coverage(kUp, v3(-17.3f, 50, -9.1f)), s(0));
  // Full melt strength from +x, level 0.5: the sun side (1, 0, 0) gets shade 0 -> 0; the
  // shade side (-1, 0, 0) shade 1, Clamp(2) = 1 -> 0.296 - 1 + 1.5 = 0.796; the top (sun on
  // the horizon, N.L = 0) shade 0.5 -> 1 -> 0.796 too.
  env.frame.sunDirection = {1, 0, 0};
  env.frame.sunMelt = 1;
  env.frame.mossLevel = 0.5f;
  expectValue(coverage(v3(1, 0, 0), at), s(0));
  expectValue(coverage(v3(-1, 0, 0), at), s(0.796f));
  // A sun 30 degrees up: the top's shade 0.5 - 0.25 = 0.25, Clamp(2 * 0.25 * 2 * 0.5) = 0.5
  // -> transition(0.296, 0.25) = 0.046; the shaded flank stays at 0.796.
  env.frame.sunDirection = {0.8660254f, 0.5f, 0};
  expectValue(coverage(kUp, at), s(0.046f));
  expectValue(coverage(v3(-1, 0, 0), at), s(0.796f));
}

// Puddles: puddleMask(N, noise, puddleLevel * exposure), noise the shared lookup's puddle
// channel, an input.
TEST(WeatherNodes, PuddleCoverage) {
  Env env;
  env.frame.puddleLevel = 0;
  expectValue(eval("weather_puddle_coverage", {kUp, s(0), s(1)}, env), s(0));
  // Full level on flat ground: smoothstep(0.45, 0.55, 0 + 1 - 0.5) = 0.5.
  env.frame.puddleLevel = 1;
  expectValue(eval("weather_puddle_coverage", {kUp, s(0), s(1)}, env), s(0.5f));
  // Exposure 0.6 -> level 0.6: 0.1 < 0.45 -> 0. Exposure 0 -> the early-out.
  expectValue(eval("weather_puddle_coverage", {kUp, s(0), s(0.6f)}, env), s(0));
  expectValue(eval("weather_puddle_coverage", {kUp, s(0), s(0)}, env), s(0));
  // A 10 degree slope never holds water.
  const float d = 3.14159265f / 180.f;
  expectValue(eval("weather_puddle_coverage", {v3(std::sin(10 * d), std::cos(10 * d), 0), s(0), s(1)}, env), s(0));
  // The shape follows the noise: 0.02 + 1 - 0.5 = 0.52 -> smoothstep(0.45, 0.55, 0.52) = 0.784.
  expectValue(eval("weather_puddle_coverage", {kUp, s(0.02f), s(1)}, env), s(0.784f));
}

// Ice: transition(noise, frostMask(F, frostLevel)) (eq. 3.20 with eq. 3.14's noisy edges),
// noise the shared transition noise, an input.
TEST(WeatherNodes, FrostCoverage) {
  Env env;
  env.frame.frostLevel = 0;
  expectValue(eval("weather_frost_coverage", {s(0), s(0)}, env), s(0));  // liquid, even at the banks
  env.frame.frostLevel = 1;
  expectValue(eval("weather_frost_coverage", {s(0.5f), s(0)}, env), s(1));  // whole river: 3 - 1 -> 1
  expectValue(eval("weather_frost_coverage", {s(1), s(0)}, env), s(1));
  // Frost 0.7 on a bank (F = 0): mask 1 -> 1; mid-stream (F = 0.5): mask 0.5^1.5 =
  // 0.3535534 -> 3 * 0.3535534 - 1 = 0.0606602 at the origin.
  env.frame.frostLevel = 0.7f;
  expectValue(eval("weather_frost_coverage", {s(0), s(0)}, env), s(1));
  expectValue(eval("weather_frost_coverage", {s(0.5f), s(0)}, env), s(0.0606602f));
  // The edge follows the noise: noise 0.3 -> 0.3 - 1 + 3 * 0.3535534 = 0.3606602.
  expectValue(eval("weather_frost_coverage", {s(0.5f), s(0.3f)}, env), s(0.3606602f));
}

// Puddle ice: max(frostLevel, 1 - smoothstep(0, 1, T)): liquid only above 0 C.
TEST(WeatherNodes, PuddleIce) {
  Env env;
  env.frame.frostLevel = 0;
  env.frame.temperature = 8;
  expectValue(eval("weather_puddle_ice", {}, env), s(0));
  env.frame.temperature = 0;
  expectValue(eval("weather_puddle_ice", {}, env), s(1));
  env.frame.temperature = -10;
  expectValue(eval("weather_puddle_ice", {}, env), s(1));
  env.frame.temperature = 0.5f;
  expectValue(eval("weather_puddle_ice", {}, env), s(0.5f));
  env.frame.temperature = 4;  // thawing: the frost level keeps it frozen
  env.frame.frostLevel = 0.6f;
  expectValue(eval("weather_puddle_ice", {}, env), s(0.6f));
}

// Hoarfrost: transition(noise, frostLevel * exposure), noise the shared transition noise.
TEST(WeatherNodes, HoarfrostCoverage) {
  Env env;
  env.frame.frostLevel = 0;
  expectValue(eval("weather_hoarfrost_coverage", {s(0), s(1)}, env), s(0));
  env.frame.frostLevel = 1;
  expectValue(eval("weather_hoarfrost_coverage", {s(0), s(1)}, env), s(1));    // 0 - 1 + 3 -> 1
  expectValue(eval("weather_hoarfrost_coverage", {s(0), s(0)}, env), s(0));    // sheltered
  expectValue(eval("weather_hoarfrost_coverage", {s(0), s(0.4f)}, env), s(0.2f));  // -1 + 1.2
  env.frame.frostLevel = 0.4f;
  expectValue(eval("weather_hoarfrost_coverage", {s(0), s(1)}, env), s(0.2f));
}

// The HLSL the backend derives from the library must define the same functions: a
// function the token map lost would compile for one target and fail for the other.
std::set<std::string> definedFunctions(std::string_view text) {
  // A definition starts a line: "<type> wg_name(". Calls are indented or follow
  // "return", "=", or another call.
  static const std::regex kDefinition(R"(^([A-Za-z_][A-Za-z0-9_]*)\s+\b(wg_[a-z0-9_]+)\s*\()");
  std::set<std::string> names;
  std::istringstream lines{std::string(text)};
  std::string line;
  while (std::getline(lines, line)) {
    std::smatch m;
    if (std::regex_search(line, m, kDefinition) && m[1].str() != "return") names.insert(m[2].str());
  }
  return names;
}

TEST(WeatherNodes, DerivedHlslLibraryDefinesTheSameFunctions) {
  auto glsl = definedFunctions(kWeatherLibrary.glsl);
  auto hlsl = definedFunctions(hlslSyntax().libraryCode(kWeatherLibrary));
  EXPECT_GE(glsl.size(), 30u);  // the library as written defines 38
  EXPECT_EQ(glsl, hlsl);
  // Every weather op's template calls a function the library or the weather maps'
  // accessors define.
  auto accessors = definedFunctions(kWeatherMapLibrary.glsl);
  glsl.insert(accessors.begin(), accessors.end());
  for (const OpDef* op : allOps()) {
    if (op->libraries.empty() || op->libraries.front() != &kWeatherLibrary) continue;
    std::string code(op->glsl);
    static const std::regex kCall(R"(\b(wg_[a-z0-9_]+)\s*\()");
    for (auto it = std::sregex_iterator(code.begin(), code.end(), kCall); it != std::sregex_iterator(); ++it)
      EXPECT_TRUE(glsl.count((*it)[1].str())) << op->name << " calls " << (*it)[1].str();
  }
}

}  // namespace
}  // namespace wg
