// Shader library text of the weather functions (seed 000, chapter 3): the same code,
// operation for operation, as nodes/weather_model.cpp, so GPU and CPU agree.
// Written in GLSL only: the HLSL backend derives its text (backends/glsl_to_hlsl.hpp).
#include "nodes/weather_shader_library.hpp"

#include "nodes/core_library.hpp"
#include "nodes/weather_noise.hpp"

namespace wg {

const ShaderLibrary kWeatherLibrary = {
    "weather",
    R"WG(// Seed 000, chapter 3. weathergen's world is Y-up: the seed's (0, 0, 1) is (0, 1, 0).
float wg_clamp01(const float x) { return clamp(x, 0.0, 1.0); }  // eq. 3.2
float wg_lerp(const float a, const float b, const float p) { return a * (1.0 - p) + b * p; }  // eq. 3.3
float wg_reflectance(const vec3 c) { return dot(vec3(0.3, 0.59, 0.11), c); }
// Eq. 3.4: geometric and normal-mapped world normals against up, cubed, gated by the
// geometric normal (a reading: see docs/weather-model.md).
float wg_inclination(const vec3 n, const vec3 nd, const float intensity) {
  float c = wg_clamp01(dot(n, vec3(0.0, 1.0, 0.0)) + dot(nd, vec3(0.0, 1.0, 0.0)) * intensity);
  // The geometric normal gates the normal-map term: overhangs never hold snow.
  return c * c * c * wg_clamp01(dot(n, vec3(0.0, 1.0, 0.0)) / 0.1);
}
// Eq. 3.5 for snow: faces that get more direct sun than level ground lose cover, in
// proportion to the melt strength (not the light's brightness).
float wg_sun_facing(const vec3 n, const vec3 towardsSun, const float melt) {
  float excess = max(dot(n, towardsSun), 0.0) - max(dot(vec3(0.0, 1.0, 0.0), towardsSun), 0.0);
  return wg_clamp01(1.0 - 1.5 * wg_clamp01(melt) * excess);
}
// Eq. 3.5 for moss, as printed with SunIntensity 0.5: the side facing away scores highest.
float wg_sun_shade(const vec3 n, const vec3 towardsSun, const float melt) {
  return wg_clamp01(0.5 - 0.5 * wg_clamp01(melt) * dot(n, towardsSun));
}
// Eq. 3.6: two panning phases of the flow map (the noise texture's g), panned at d * t
// flow cells (8 per tile) per second.
float wg_wind_flow(const vec2 xz, const vec2 d, const float t) {
  vec2 uv = xz * 0.03125;
  vec2 pan = d * (t * 0.125);
  return wg_weather_noise(uv + pan).y + 0.5 * wg_weather_noise(uv + pan.yx).y;
}
// Eq. 3.7 with f_wind given: N . (d.x, 0, d.y) f_wind, with the zero term left out.
float wg_wind_from_flow(const vec3 n, const vec2 d, const float flow, const float intensity) {
  return wg_clamp01(dot(n.xz, d) * flow + intensity);
}
float wg_wind_influence(const vec3 n, const vec2 xz, const vec2 d, const float intensity, const float t) {
  return wg_wind_from_flow(n, d, wg_wind_flow(xz, d, t), intensity);
}
// Eq. 3.8
float wg_height(const float y, const float lo, const float hi) {
  return wg_clamp01((y - lo) / max(hi - lo, 1e-3));
}
// Eq. 3.9
float wg_height_inverted(const float y, const float lo, const float hi) { return 1.0 - wg_height(y, lo, hi); }
// Eq. 3.10
vec3 wg_snow_displacement(const float noise, const float progress, const float maxSnowHeight, const vec3 n) {
  return (wg_clamp01(noise + 0.75) * progress * maxSnowHeight) * n;
}
// Eq. 3.12
vec3 wg_terrain_slope(const float h0, const float hu, const float hv, const float intensity) {
  return cross(vec3(1.0, 0.0, intensity * (hu - h0)), vec3(0.0, 1.0, intensity * (hv - h0)));
}
// Eq. 3.13: the slope's height-map (u, v) lie along world (x, z).
float wg_terrain_orientation(const vec3 slope, const vec3 n, const float tangentNormalZ, const float intensity) {
  return dot(slope.xy, n.xz) * tangentNormalZ * intensity;
}
float wg_transition(const float noise, const float p) { return wg_clamp01(noise - 1.0 + 3.0 * p); }  // eq. 3.14
// Eq. 3.14 for melting snow: patches shaped mostly by patchNoise (the flow channel, 4 m
// cells), stretched to eq. 3.14's range of levels, covered where it gives half cover.
// The soft edge widens with the pixel's footprint (metres, fwidth of the world xz), so
// distant patches blur instead of aliasing; at most 0.5, so level 0 stays 0. Only the
// lit frame: AOVs show a point's value, as the CPU (no footprint) does.
float wg_thaw_patches(const float noise, const float patchNoise, const float p, const vec2 footprint) {
  float stretched = wg_clamp01(0.5 + 2.3 * (wg_lerp(noise, patchNoise, 0.8) - 0.5));
  float blur = 0.5 * max(footprint.x, footprint.y) * float(frame_debugView == 0u);
  float edge = min(0.15 + blur, 0.5);
  return smoothstep(0.5 - edge, 0.5 + edge, wg_transition(stretched, p));
}
// Eq. 3.1: inclination gates every other term.
float wg_prediction(const float inc, const float sun, const float h, const float terrain, const float wind,
                    const vec4 w) {
  return wg_clamp01(inc * (w.x * sun * w.z * h + w.w * terrain + w.y * wind));
}
// Eq. 3.15 as a continuous level.
float wg_wetness(const float temperature, const float level, const float exposure) {
  return wg_clamp01(level) * wg_clamp01(exposure) * smoothstep(0.0, 1.0, temperature);
}
// Eq. 3.16-3.17 by porosity (Lagarde 2013): water darkens a dielectric it soaks into,
// not a metal, and a metal's film keeps up to 0.15 of its roughness.
vec3 wg_wet_diffuse(const vec3 d, const float p, const float metallic) { return d * wg_lerp(1.0, 0.7, p * (1.0 - metallic)); }
float wg_wet_roughness(const float r, const float p, const float metallic) {
  return max(wg_clamp01(r - p), metallic * min(r, 0.15));
}
// Specular anti-aliasing (Kaplanyan, Hill, Patney, Lefohn 2016): water makes a surface
// glossy, and a normal map that varies within a pixel then lights single pixels as
// glints, so the normal's screen-space variance widens the lobe (alpha = r^2, the kernel
// capped at 0.18). Only the lit frame: AOVs show a point's value, as the CPU does.
float wg_specular_aa(const float r, const vec3 dndx, const vec3 dndy) {
  float variance = 0.25 * (dot(dndx, dndx) + dot(dndy, dndy));
  // Selects, not branches: both sides are a few instructions.
  float kernel = min(2.0 * variance, 0.18) * float(frame_debugView == 0u);
  float widened = sqrt(sqrt(min(r * r * r * r + kernel, 1.0)));
  return kernel > 0.0 ? widened : r;
}
// Eq. 3.18: a panning ripple added to the tangent-space normal while it rains. Its two
// slopes are two smooth noise fields at the panned point (the ripple b and the transition
// r, 2 and 1.5 cells per metre), faded out where a pixel's footprint (footprint: fwidth
// of the world xz, metres) spans more than a quarter of a ripple cell, so it never
// breaks up into sub-pixel glints; the CPU evaluator's footprint is 0.
vec3 wg_wet_normal(const vec3 n, const vec2 xz, const float p, const float precipitation, const float t,
                   const vec2 footprint) {
  // No rain (rain 0) or a dry point (p 0): no flowing water, the normal as it was.
  float strength = (p > 0.0 ? 2.0 * 0.25 : 0.0) * smoothstep(0.0, 0.1, precipitation);
  vec2 uv = xz * 0.03125 + vec2(0.5, 0.01) * (p * t * 0.015625);  // ripple cells: 64 per tile
  vec4 noise = wg_weather_noise(uv);
  float cellsPerPixel = 2.0 * max(footprint.x, footprint.y);
  vec2 pan = (noise.zx - 0.5) * ((1.0 - smoothstep(0.25, 0.75, cellsPerPixel)) * strength);
  return n + vec3(pan, 0.0);
}
// Eq. 3.19
vec3 wg_desaturate(const vec3 c, const float p) { return p * dot(vec3(0.3, 0.59, 0.11), c) + (1.0 - p) * c; }
float wg_detail_mask(const vec3 d) { return wg_clamp01(wg_desaturate(d, 1.0).x); }  // eq. 3.19
// Table 4.1: the albedo's reflectance is mapped into the measured band.
vec3 wg_band_albedo(const vec3 d, const vec3 tint, const float lo, const float hi, const float spread) {
  float v = wg_lerp(lo, hi, wg_clamp01(wg_detail_mask(d) * spread));
  return tint / wg_reflectance(tint) * v;
}
vec3 wg_snow_albedo(const vec3 d) { return wg_band_albedo(d, vec3(0.97, 0.985, 1.0), 0.9, 0.95, 2.0); }
vec3 wg_moss_albedo(const vec3 d) { return wg_band_albedo(d, vec3(0.45, 0.75, 0.2), 0.25, 0.53, 1.5); }
// Cracks and trapped bubbles, where the frozen surface's tangent normal bends, go to the
// band's top.
vec3 wg_ice_albedo(const vec3 d, const vec3 tn) {
  float cracks = smoothstep(0.3, 0.6, length(tn.xy));
  vec3 tint = vec3(0.85, 0.95, 1.0);
  return tint / wg_reflectance(tint) * wg_lerp(0.5, 0.7, wg_clamp01(wg_detail_mask(d) * 3.0 + cracks));
}
// Eq. 3.20, faded in over the first tenth of freezing.
float wg_frost_mask(const float frostMap, const float frost) {
  float e = wg_lerp(0.0, 5.0, 1.0 - wg_clamp01(frost));
  return pow(max(1.0 - wg_clamp01(frostMap), 1e-4), e) * wg_clamp01(frost * 10.0);
}
// Section 5.1.2: within 8 degrees of up (cos 8 = 0.990268), full within 4 (cos 4 = 0.997564).
float wg_puddle_mask(const vec3 n, const float noise, const float level) {
  float flatness = smoothstep(0.99026807, 0.99756405, dot(n, vec3(0.0, 1.0, 0.0)));
  return flatness * smoothstep(0.45, 0.55, noise + level - 0.5);
}
// A term of eq. 3.1 under its switch: f when on (1), `neutral` when off (0), blended in
// between, as a slope blend's terms are. Where the injected switch is a constant 0 or 1,
// spirv-opt folds the mix to one side and drops what is off.
float wg_switched_term(const float on, const float f, const float neutral) { return mix(neutral, f, on); }
// Eq. 3.1 with switches: shape = (minHeight, maxHeight, inclination intensity, unused),
// terms = (inclination, sun, height, wind).
// A switched-off factor counts as 1, and so does its weight (w1 sun, w3 height).
// windFlow is eq. 3.6's f_wind at p (weather_wind_flow, computed per vertex).
float wg_shaped_prediction(const vec3 n, const vec3 nd, const vec3 p, const float terrain, const float windFlow, vec4 w,
                           const vec4 shape, const vec4 terms) {
  w.x = wg_switched_term(terms.y, w.x, 1.0);
  w.z = wg_switched_term(terms.z, w.z, 1.0);
  float inc = wg_switched_term(terms.x, wg_inclination(n, nd, shape.z), 1.0);
  float sun = wg_switched_term(terms.y, wg_sun_facing(n, frame_sunDirection, frame_sunMelt), 1.0);
  float h = wg_switched_term(terms.z, wg_height(p.y, shape.x, shape.y), 1.0);
  float wind = wg_switched_term(terms.w, wg_wind_from_flow(n, frame_windDirection, windFlow, frame_windIntensity), 0.0);
  return wg_prediction(inc, sun, h, terrain, wind, w);
}
// No effect branches on its level: at level 0 its transition (eq. 3.14) of a noise of at
// most 1 is exactly 0, and the weather's one uniform branch skips the lot while every
// level is 0.
// `noise` is the shared transition noise (eq. 3.14's NoiseMap, wg_weather_noise_at(p).x),
// `patchNoise` its flow channel (.y), `footprint` fwidth of the world xz. Settling snow
// covers as eq. 3.14 prints; melting snow (above 0 C, eq. 3.15's 1 C ramp) retreats in
// patches.
float wg_snow_coverage(const vec3 n, const vec3 nd, const vec3 p, const vec3 diffuse, const float terrain,
                       const float windFlow, const float exposure, const vec4 w, const vec4 shape, const vec4 terms,
                       const float noise, const float patchNoise, const vec2 footprint) {
  float level = wg_clamp01(frame_snowLevel) * wg_clamp01(exposure);
  float fp = wg_shaped_prediction(n, nd, p, terrain, windFlow, w, shape, terms);
  float settling = wg_transition(0.5 * noise + 0.5 * (1.0 - wg_detail_mask(diffuse)), fp * level);
  float melting = smoothstep(0.0, 1.0, frame_temperature);
  return wg_lerp(settling, wg_thaw_patches(noise, patchNoise, fp * level, footprint), melting);
}
vec3 wg_snow_offset(const vec3 n, const vec3 p, const float windFlow, const float exposure, const vec4 w,
                    const vec4 shape, const vec4 terms, const float maxSnowHeight, const float noise) {
  float level = wg_clamp01(frame_snowLevel) * wg_clamp01(exposure);
  float fp = wg_shaped_prediction(n, n, p, 0.0, windFlow, w, shape, terms);
  return wg_snow_displacement(noise, fp * level, maxSnowHeight, n);
}
float wg_moss_coverage(const vec3 n, const vec3 p, const vec3 diffuse, const vec4 w, const vec4 shape,
                       const float noise) {
  float level = wg_clamp01(frame_mossLevel);
  float shade = wg_sun_shade(n, frame_sunDirection, frame_sunMelt);
  float low = wg_height_inverted(p.y, shape.x, shape.y);
  float facing = wg_clamp01(1.0 + 2.0 * dot(n, vec3(0.0, 1.0, 0.0)));  // not on overhangs
  float predicted = wg_clamp01(w.x * shade * w.z * low) * facing;
  return wg_transition(0.5 * noise + 0.5 * (1.0 - wg_detail_mask(diffuse)), predicted * level);
}
float wg_puddle_coverage(const vec3 n, const float noise, const float exposure) {
  float level = wg_clamp01(frame_puddleLevel) * wg_clamp01(exposure);
  return (level > 0.0 ? 1.0 : 0.0) * wg_puddle_mask(n, noise, level);  // the mask alone is not 0 at level 0
}
// Standing water is liquid only above 0 C; the frost level keeps it frozen while it thaws.
float wg_puddle_ice() {
  return max(wg_clamp01(frame_frostLevel), 1.0 - smoothstep(0.0, 1.0, frame_temperature));
}
// Eq. 3.20 with eq. 3.14's noisy edges.
float wg_frost_coverage(const float frostMap, const float noise) {
  return wg_transition(noise, wg_frost_mask(frostMap, frame_frostLevel));
}
float wg_hoarfrost_coverage(const float noise, const float exposure) {
  float level = wg_clamp01(frame_frostLevel) * wg_clamp01(exposure);
  return wg_transition(noise, level);
}
// A layer's own relief: the transition noise (r, the shared lookup's `height`) read as a
// height field of `amplitude` metres, its slope by forward differences two noise texels
// (12.5 cm, kReliefStep) along x and z, tilted into the tangent frame (n the geometric
// normal, tangent its tangent): a tangent-space normal for cover().
vec3 wg_noise_relief(const vec3 p, const float height, const float amplitude, const vec3 n, const vec4 tangent) {
  // The shared lookup's uv, offset by kReliefStep (1/256 of a tile): the same bits as
  // offsetting p, since the tile scale is a power of two.
  vec2 uv = wg_weather_noise_uv(p);
  float hx = wg_weather_noise(uv + vec2(0.00390625, 0.0)).x;
  float hz = wg_weather_noise(uv + vec2(0.0, 0.00390625)).x;
  // The slope negated (height minus neighbour), so the normal needs no negation.
  vec3 downhill = vec3(height - hx, 0.0, height - hz) * (amplitude / 0.125);  // metres per metre
  vec3 b = cross(n, tangent.xyz) * tangent.w;
  return vec3(dot(downhill, tangent.xyz), dot(downhill, b), 1.0);
}
// Tangent-space normal to world space; the fragment stage's frame is already orthonormal.
vec3 wg_tangent_to_world(const vec3 n, const vec3 normal, const vec4 tangent) {
  vec3 b = cross(normal, tangent.xyz) * tangent.w;
  return wg_safe_normalize(tangent.xyz * n.x + b * n.y + normal * n.z);
}
// The sky-exposure map holds, per texel of skyExposureRegion, the world height of the
// highest surface seen from above. A point is open to the sky when nothing is more
// than 10 cm above it and sheltered under anything 50 cm above; outside the region,
// everything is open sky. The lookup moves 1.5 texels out along the normal's xz, so
// a steep face is not shadowed by its own top edge. Percentage-closer filtering: the
// 2x2 texels of the linear footprint (textureGather's x (0,1), y (1,1), z (1,0),
// w (0,0)) are each compared with the point, then weighted bilinearly.
// 2048.0 is weather::kSkyExposureResolution, 1.5 kSkyExposureNormalOffset.
vec2 wg_sky_exposure_uv(const vec3 p, const vec3 n) {
  return (p.xz - frame_skyExposureRegion.xy) * frame_skyExposureRegion.zw + n.xz * (1.5 / 2048.0);
}
float wg_exposure_from_map(const vec3 p, const vec3 n, const vec4 occluderHeights) {
  vec2 uv = wg_sky_exposure_uv(p, n);
  vec4 open = 1.0 - smoothstep(vec4(p.y + 0.1), vec4(p.y + 0.5), occluderHeights);
  vec2 f = fract(uv * 2048.0 - 0.5);
  float exposed = mix(mix(open.w, open.z, f.x), mix(open.x, open.y, f.x), f.y);
  // Inside: uv is its own clamp to [0, 1] (no short-circuit branches).
  bool inside = all(bvec3(frame_skyExposureRegion.z > 0.0, equal(uv, clamp(uv, 0.0, 1.0))));
  return inside ? exposed : 1.0;  // a select of two values, not a branch
}
// Eq. 3.11: world position to height-map coordinates.
vec2 wg_terrain_coord(const vec3 p) { return (vec2(p.x, p.z) - frame_terrainRegion.xy) * frame_terrainRegion.zw; }
)WG",
    {&kCoreLibrary, &weather::kWeatherNoiseLibrary}};

}  // namespace wg
