// The weather functions of seed 000, chapter 3, on the CPU. The shader library in
// nodes/weather_shader_library.cpp is the same code in GLSL and HLSL; the CPU
// evaluator and constant folding use these. docs/weather-model.md explains each
// equation and the reading chosen where the print is ambiguous.
#pragma once
#include <vector>

#include <glm/glm.hpp>

#include "nodes/op_definition.hpp"

namespace wg::weather {

// The seed works in UE4's Z-up world; weathergen's world is Y-up, so the seed's
// (0, 0, 1) "up" is (0, 1, 0) here.
inline constexpr glm::vec3 kUp{0.f, 1.f, 0.f};
// Eq. 3.19's desaturation weights; also how we measure an albedo's reflectance
// against Table 4.1.
inline constexpr glm::vec3 kDetailWeights{0.3f, 0.59f, 0.11f};

// Table 4.1: measured reflectance bands (Remember Me, GDC 2013).
struct Band {
  float low, high;
};
inline constexpr Band kSnowBand{0.90f, 0.95f};
inline constexpr Band kGrassBand{0.25f, 0.53f};
inline constexpr Band kOceanIceBand{0.50f, 0.70f};

// Surface constants of the weather layers.
inline constexpr float kWaterSpecular = 0.25f;  // UE4 specular: F0 = 0.08 * 0.25 = 0.02 (water, IOR 1.33)
inline constexpr float kIceSpecular = 0.225f;   // F0 = 0.018 (ice, IOR 1.31)
inline constexpr float kPuddleRoughness = 0.02f;  // still water: near mirror
inline constexpr float kSnowRoughness = 0.65f;    // fresh snow is a rough, forward-scattering dielectric
inline constexpr float kIceRoughness = 0.12f;
inline constexpr float kMossRoughness = 0.85f;    // the seed tunes moss "as if it were grass"
inline constexpr float kFrostRoughness = 0.45f;   // hoarfrost on a road: fine crystals

float reflectance(glm::vec3 albedo);  // dot(kDetailWeights, albedo)

float clamp01(float x);                      // eq. 3.2
float lerp(float a, float b, float p);       // eq. 3.3
// Eq. 3.4: Clamp(N.up + (Nd.up) * intensity)^3, Nd the normal-mapped world normal,
// times Clamp(N.up / 0.1) so undersides never hold snow whatever the normal map does.
float inclination(glm::vec3 normal, glm::vec3 detailNormal, float intensity);
// Eq. 3.5 for snow, relative to level ground:
// Clamp(1 - 1.5 melt (max(N . L, 0) - max(up . L, 0))). Faces that get more direct sun
// than level ground lose cover; level ground keeps snowLevel's cover under any sun.
float sunFacing(glm::vec3 normal, glm::vec3 towardsSun, float melt);
// Eq. 3.5 for moss, as printed with SunIntensity 0.5: Clamp(0.5 - 0.5 melt (N . L)).
// The side facing away from the sun scores highest, the side facing it lowest.
float sunShade(glm::vec3 normal, glm::vec3 towardsSun, float melt);
// Eq. 3.6: f_pan(h, v) = flow(xz + (h, v) * time); f_wind(d) = f_pan(d.x, d.y) + 0.5 f_pan(d.y, d.x),
// flow the noise texture's g channel (nodes/weather_noise.hpp), panned (h, v) * time cells.
float windFlow(glm::vec2 xz, glm::vec2 direction, float time);
// Eq. 3.7 with f_wind given: Clamp(N . (d.x, 0, d.y) * flow + windIntensity).
float windFromFlow(glm::vec3 normal, glm::vec2 direction, float flow, float intensity);
// Eq. 3.6-3.7: windFromFlow of windFlow at xz.
float windInfluence(glm::vec3 normal, glm::vec2 xz, glm::vec2 direction, float intensity, float time);
float height(float y, float minHeight, float maxHeight);          // eq. 3.8
float heightInverted(float y, float minHeight, float maxHeight);  // eq. 3.9
// Eq. 3.10: (Clamp(noise + 0.75) * progress * maxSnowHeight) * N.
glm::vec3 snowDisplacement(float noise, float progress, float maxSnowHeight, glm::vec3 normal);
// Eq. 3.12: (1, 0, I (hH - h0)) x (0, 1, I (hV - h0)) in height-map space (u, v, height).
glm::vec3 terrainSlope(float h0, float hShiftU, float hShiftV, float intensity);
// Eq. 3.13: ((slope * (1, 1, 0)) . N) (TN . (0, 0, 1)) intensity, the slope's u, v -> world x, z.
float terrainOrientation(glm::vec3 slope, glm::vec3 normal, float tangentNormalZ, float intensity);
float transition(float noise, float progress);  // eq. 3.14: Clamp(noise - 1 + 3 p)
// Eq. 3.14 for melting snow: patches, not a partial cover everywhere. The shape (mostly
// patchNoise, the noise texture's flow channel) is covered where eq. 3.14 gives more than
// half cover, with a soft edge; 0 at progress 0, 1 from progress 2/3.
float thawPatches(float noise, float patchNoise, float progress);
// Eq. 3.1, grouped so that inclination gates every other term:
// Clamp(inc * (w1 sun * w3 height + w4 terrain + w2 wind)).
float prediction(float inc, float sun, float heightTerm, float terrain, float wind, glm::vec4 weights);
// Eq. 3.15 as a continuous level: wetnessLevel * exposure * smoothstep(0, 1 C, T).
float wetness(float temperature, float wetnessLevel, float exposure);
// Eq. 3.16-3.17 by porosity (Lagarde 2013): water darkens what it soaks into, a
// dielectric, not a metal, and a metal's water film keeps a little of its roughness.
glm::vec3 wetDiffuse(glm::vec3 diffuse, float p, float metallic = 0.f);  // diffuse * Lerp(1, 0.7, p (1 - m))
float wetRoughness(float roughness, float p, float metallic = 0.f);      // max(Clamp(R - p), m min(R, 0.15))
// Eq. 3.18: normal + Pan((0.5 p, 0.01 p)) * (1, 1, 0), flowing only while it rains; the
// pan's two slopes are the noise texture's b (ripple) and r channels at the panned point.
// The shader also fades it by its pixel's footprint; a CPU point has none.
glm::vec3 wetNormal(glm::vec3 tangentNormal, glm::vec2 xz, float p, float precipitation, float time);
glm::vec3 desaturate(glm::vec3 in, float p);  // eq. 3.19
float detailMask(glm::vec3 diffuse);          // eq. 3.19 with p = 1: Clamp(d . diffuse)
glm::vec3 snowAlbedo(glm::vec3 diffuse);      // eq. 3.19 + Table 4.1 snow band
glm::vec3 mossAlbedo(glm::vec3 diffuse);      // detail mask * green, grass band
// Ocean-ice band: darker diffuse fills first (spread 3), and cracks and trapped bubbles,
// where the frozen surface's tangent normal bends (|xy| 0.3-0.6), go to the band's top.
glm::vec3 iceAlbedo(glm::vec3 diffuse, glm::vec3 tangentNormal = {0.f, 0.f, 1.f});
// Eq. 3.20: (1 - F)^Lerp(0, 5, 1 - frost), faded in over the first tenth of freezing.
float frostMask(float frostMap, float frostLevel);
// Section 5.1.2: flat (within 8 degrees of up) and where high-contrast noise allows.
float puddleMask(glm::vec3 normal, float noise, float puddleLevel);

// The per-effect coverage functions the injection pass emits. None branches on its
// level: at level 0 each is exactly 0 through its arithmetic (eq. 3.14's transition of a
// noise of at most 1), puddles through one select. `noise` is the
// one lookup they share: eq. 3.14's NoiseMap, the noise texture's r channel at the point
// (noiseAt(position).x), and for puddles its a channel.
struct SnowShape {
  glm::vec4 weights{2.f, 0.5f, 2.f, 0.5f};  // w1 sun, w2 wind, w3 height, w4 terrain
  float minHeight = -50.f, maxHeight = 50.f;
  float inclinationIntensity = 0.5f;
  // Use inclination, sun, height, wind (on above 0.5). A switched-off factor counts as 1 and so
  // does its weight (w1 for the sun, w3 for the height): the weights are renormalised.
  glm::vec4 terms{1.f, 1.f, 1.f, 1.f};
};
// `windFlow` is eq. 3.6's f_wind at the point (windFlow()), read where the wind term is on.
// Settling snow (below 0 C) covers as eq. 3.14 prints; melting snow (above, over the 1 C
// ramp of eq. 3.15) in thawPatches(noise, patchNoise), patchNoise the shared lookup's
// flow channel (noiseAt(position).y).
float snowCoverage(const FrameState& frame, glm::vec3 normal, glm::vec3 detailNormal, glm::vec3 position,
                   glm::vec3 diffuse, float terrain, float windFlow, float exposure, const SnowShape& shape, float noise,
                   float patchNoise);
glm::vec3 snowOffset(const FrameState& frame, glm::vec3 normal, glm::vec3 position, float windFlow, float exposure,
                     const SnowShape& shape, float maxSnowHeight, float noise);
float mossCoverage(const FrameState& frame, glm::vec3 normal, glm::vec3 position, glm::vec3 diffuse,
                   const SnowShape& shape, float noise);
float puddleCoverage(const FrameState& frame, glm::vec3 normal, float noise, float exposure);
// How frozen standing water is: liquid only above 0 C (the 1 C ramp of eq. 3.15), and
// the frost level keeps it frozen while it thaws: max(frost, 1 - smoothstep(0, 1 C, T)).
float puddleIce(const FrameState& frame);
// Eq. 3.20's frost mask with eq. 3.14's noisy edges: transition(coverageNoise(p), mask).
float frostCoverage(const FrameState& frame, float frostMap, float noise);
float hoarfrostCoverage(const FrameState& frame, float noise, float exposure);

// A layer's own relief: the transition noise read as a height field of `amplitude`
// metres per unit of noise over world xz (height: its value at the point), sloped by
// forward differences kReliefStep along x and z and tilted into the tangent frame
// (normal, tangent xyz and bitangent sign w): the tangent-space normal the layer takes on.
inline constexpr float kSnowReliefAmplitude = 0.25f;  // metres per unit of noise: wind-drifted bumps
inline constexpr float kIceReliefAmplitude = 0.04f;   // a frozen surface's slight undulation
inline constexpr float kReliefStep = 0.125f;          // metres: two noise texels
glm::vec3 noiseRelief(glm::vec3 position, float height, float amplitude, glm::vec3 normal, glm::vec4 tangent);

// The sky-exposure map (docs/weather-model.md, "Sky exposure"): texels per side over the
// scene's xz extent, about 6 cm on the 122 m rocks scene.
inline constexpr int kSkyExposureResolution = 2048;
// The lookup moves this many texels out along the normal's xz (normal offset), so a steep
// face is not sheltered by its own top edge.
inline constexpr float kSkyExposureNormalOffset = 1.5f;
// Sky exposure from one occluder height above a point (1 open, 0 sheltered).
float skyExposure(float pointHeight, float occluderHeight);
// The map's percentage-closer filter: each of the 2x2 texels around uv (Vulkan's linear
// footprint, clamped) compared with the point's height, the results weighted bilinearly,
// so an occluder's edge blurs by at most one texel and no height is ever interpolated.
float filteredSkyExposure(const std::vector<float>& heights, int resolution, glm::vec2 uv, float pointHeight);

}  // namespace wg::weather
