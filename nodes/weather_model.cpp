#include "nodes/weather_model.hpp"

#include <algorithm>
#include <cmath>

#include "nodes/weather_noise.hpp"

namespace wg::weather {

namespace {
// Sky exposure: an occluder within 10 cm above is the surface itself (a neighbouring
// texel of 45-degree ground is 1.4 texels = 9 cm higher); one 50 cm or more above
// shelters the point completely.
constexpr float kShelterClearance = 0.1f;
constexpr float kShelterFull = 0.5f;
// Eq. 3.4 gate: faces within this much of vertical (as n.up, about 6 degrees) fade in.
constexpr float kFacingRamp = 0.1f;
// Eq. 3.5 for snow: at full melt strength a face that gets 2/3 of a full sun more direct
// sun than level ground loses all cover (a 30-degree slope facing a sun on the horizon
// gets 0.5 more, and keeps f_sun = 0.25).
constexpr float kSunMeltScale = 1.5f;
// Eq. 3.5 for moss: the printed SunIntensity offset; also the scale of the sun term, so
// full sun maps N . L in [-1, 1] onto [1, 0].
constexpr float kMossShadeBias = 0.5f;
// Moss clings to tops and sides; overhangs fade out by 30 degrees below the horizontal.
constexpr float kMossOverhangRamp = 2.f;
// Eq. 3.10: the displacement noise is brightened so it never opens holes.
constexpr float kNoiseBrightening = 0.75f;
// Eq. 3.12: the height map is shifted by 0.05 texture units to measure slope.
constexpr float kTerrainShift = 0.05f;
// Eq. 3.16: wet diffuse is toned down to 70 %.
constexpr float kWetDarkening = 0.7f;
// A wet metal's water film keeps this much of its roughness at most (Lagarde 2013: metals
// are not porous; the film smooths them, never to a mirror).
constexpr float kWetMetalRoughness = 0.15f;
// Eq. 3.18: the flowing-water normal pans at (0.5 p, 0.01 p) units per second.
constexpr glm::vec2 kWetFlowSpeed{0.5f, 0.01f};
// Eq. 3.20: the frost gradient's exponent runs from 0 to 5.
constexpr float kFrostExponentMax = 5.f;
// Liquid water has no frozen banks: the frost mask fades in over the first 1/10 of frost.
constexpr float kFrostFadeIn = 10.f;
// Section 5.1.2: puddles only within 8 degrees of up; fully formed within 4.
const float kCosPuddleMaxSlope = std::cos(glm::radians(8.f));
const float kCosPuddleFullSlope = std::cos(glm::radians(4.f));
// Puddle shapes: the noise texture's high-contrast a channel, with a soft 0.1-wide edge.
constexpr float kPuddleEdge = 0.05f;
// The noise texture (nodes/weather_noise.hpp): world xz to tile coordinates, and the
// tile coordinates of one lattice cell of the panned channels. All are powers of two,
// so the shaders' multiplies round exactly as these do.
constexpr float kTilePerMetre = 1.f / kNoiseTile;
constexpr float kTilePerFlowCell = 1.f / static_cast<float>(kFlowCells);
constexpr float kTilePerRippleCell = 1.f / static_cast<float>(kRippleCells);
constexpr float kRippleStrength = 0.25f;
// Temperatures (C) over which rain turns into wetness (eq. 3.15's T > 0, made continuous).
constexpr float kWetTemperatureRamp = 1.f;
// Thaw patches: snow melting above 0 C retreats in patches shaped by the noise texture's
// flow channel (4 m cells) with a fifth of the transition channel (1.5/m) for ragged
// edges, its contrast stretched so the patches take the same range of levels as eq.
// 3.14's transition (about 2 % to 98 % of the noise in [0, 1]); a patch's edge is where
// eq. 3.14 gives half cover, softened over 0.15 of its value either side (the shader
// widens it by half the pixel's footprint in metres, up to 0.5, so distant patches
// do not alias; a point has no footprint).
constexpr float kThawShapeWeight = 0.8f;
constexpr float kThawContrast = 2.3f;
constexpr float kThawEdge = 0.15f;
// Precipitation over which the flowing-water normal fades in (eq. 3.15's P > 0).
constexpr float kRainFlowRamp = 0.1f;
// Maps a typical diffuse reflectance (0.1-0.5) across each measured band.
constexpr float kSnowBandSpread = 2.f, kMossBandSpread = 1.5f, kIceBandSpread = 3.f;
// Hues, normalised to reflectance 1 below: slightly blue snow, moss green, blue-white ice.
constexpr glm::vec3 kSnowTint{0.97f, 0.985f, 1.f};
constexpr glm::vec3 kMossTint{0.45f, 0.75f, 0.2f};
constexpr glm::vec3 kIceTint{0.85f, 0.95f, 1.f};
// Ice cracks and bubbles: the frozen surface's tangent-normal bend (|xy|) over which ice
// goes from its detail-mask shade to the band's top.
constexpr Band kIceCrackBend{0.3f, 0.6f};
// Height differences below this (metres) would divide by zero in eq. 3.8.
constexpr float kMinHeightRange = 1e-3f;
// Eq. 3.20 raises 1 - F to a power that may be 0; pow(0, 0) is undefined in shaders.
constexpr float kMinFrostBase = 1e-4f;

glm::vec3 bandAlbedo(glm::vec3 diffuse, glm::vec3 tint, Band band, float spread) {
  float value = lerp(band.low, band.high, clamp01(detailMask(diffuse) * spread));
  return tint / reflectance(tint) * value;
}

float smoothStep(float e0, float e1, float x) {
  float t = clamp01((x - e0) / (e1 - e0));
  return t * t * (3.f - 2.f * t);
}
}  // namespace

float reflectance(glm::vec3 albedo) { return glm::dot(kDetailWeights, albedo); }

float clamp01(float x) { return std::min(std::max(x, 0.f), 1.f); }

float lerp(float a, float b, float p) { return a * (1.f - p) + b * p; }

float inclination(glm::vec3 normal, glm::vec3 detailNormal, float intensity) {
  float c = clamp01(glm::dot(normal, kUp) + glm::dot(detailNormal, kUp) * intensity);
  // The geometric normal gates the normal-map term: an up-facing detail facet on an
  // overhang must not hold snow ("weather affects the top more than the sides").
  float facing = clamp01(glm::dot(normal, kUp) / kFacingRamp);
  return c * c * c * facing;
}

float sunFacing(glm::vec3 normal, glm::vec3 towardsSun, float melt) {
  float excess = std::max(glm::dot(normal, towardsSun), 0.f) - std::max(glm::dot(kUp, towardsSun), 0.f);
  return clamp01(1.f - kSunMeltScale * clamp01(melt) * excess);
}

float sunShade(glm::vec3 normal, glm::vec3 towardsSun, float melt) {
  return clamp01(kMossShadeBias - kMossShadeBias * clamp01(melt) * glm::dot(normal, towardsSun));
}

float windFlow(glm::vec2 xz, glm::vec2 direction, float time) {
  glm::vec2 uv = xz * kTilePerMetre;
  glm::vec2 pan = direction * (time * kTilePerFlowCell);
  return sampleNoise(uv + pan).y + 0.5f * sampleNoise(uv + glm::vec2(pan.y, pan.x)).y;
}

float windFromFlow(glm::vec3 normal, glm::vec2 direction, float flow, float intensity) {
  // N . (d.x, 0, d.y) f_wind, with the zero term left out as the shaders do.
  return clamp01(glm::dot(glm::vec2(normal.x, normal.z), direction) * flow + intensity);
}

float windInfluence(glm::vec3 normal, glm::vec2 xz, glm::vec2 direction, float intensity, float time) {
  return windFromFlow(normal, direction, windFlow(xz, direction, time), intensity);
}

float height(float y, float minHeight, float maxHeight) {
  return clamp01((y - minHeight) / std::max(maxHeight - minHeight, kMinHeightRange));
}

float heightInverted(float y, float minHeight, float maxHeight) { return 1.f - height(y, minHeight, maxHeight); }

glm::vec3 snowDisplacement(float noise, float progress, float maxSnowHeight, glm::vec3 normal) {
  return (clamp01(noise + kNoiseBrightening) * progress * maxSnowHeight) * normal;
}

glm::vec3 terrainSlope(float h0, float hShiftU, float hShiftV, float intensity) {
  return glm::cross(glm::vec3(1.f, 0.f, intensity * (hShiftU - h0)), glm::vec3(0.f, 1.f, intensity * (hShiftV - h0)));
}

float terrainOrientation(glm::vec3 slope, glm::vec3 normal, float tangentNormalZ, float intensity) {
  glm::vec3 horizontal(slope.x, 0.f, slope.y);  // height-map (u, v) lie along world (x, z)
  return glm::dot(horizontal, normal) * tangentNormalZ * intensity;
}

float transition(float noise, float progress) { return clamp01(noise - 1.f + 3.f * progress); }

float thawPatches(float noise, float patchNoise, float progress) {
  float shape = lerp(noise, patchNoise, kThawShapeWeight);
  float stretched = clamp01(0.5f + kThawContrast * (shape - 0.5f));
  return smoothStep(0.5f - kThawEdge, 0.5f + kThawEdge, transition(stretched, progress));
}

float prediction(float inc, float sun, float heightTerm, float terrain, float wind, glm::vec4 w) {
  return clamp01(inc * (w.x * sun * w.z * heightTerm + w.w * terrain + w.y * wind));
}

float wetness(float temperature, float wetnessLevel, float exposure) {
  return clamp01(wetnessLevel) * clamp01(exposure) * smoothStep(0.f, kWetTemperatureRamp, temperature);
}

glm::vec3 wetDiffuse(glm::vec3 diffuse, float p, float metallic) {
  return diffuse * lerp(1.f, kWetDarkening, p * (1.f - metallic));
}

float wetRoughness(float roughness, float p, float metallic) {
  return std::max(clamp01(roughness - p), metallic * std::min(roughness, kWetMetalRoughness));
}

glm::vec3 wetNormal(glm::vec3 tangentNormal, glm::vec2 xz, float p, float precipitation, float time) {
  // No rain (rain 0) or a dry point (p 0): no flowing water, the normal as it was.
  float strength = (p > 0.f ? 2.f * kRippleStrength : 0.f) * smoothStep(0.f, kRainFlowRamp, precipitation);
  glm::vec2 uv = xz * kTilePerMetre + kWetFlowSpeed * (p * time * kTilePerRippleCell);
  // One lookup gives both slopes: the ripple and the transition noise at the panned point.
  // A point has no footprint, so nothing fades (the shader fades by its pixel's).
  glm::vec4 n = sampleNoise(uv);
  glm::vec2 pan(n.z - 0.5f, n.x - 0.5f);
  return tangentNormal + glm::vec3(pan * strength, 0.f);
}

glm::vec3 desaturate(glm::vec3 in, float p) { return p * glm::dot(kDetailWeights, in) + (1.f - p) * in; }

float detailMask(glm::vec3 diffuse) { return clamp01(desaturate(diffuse, 1.f).x); }

glm::vec3 snowAlbedo(glm::vec3 diffuse) { return bandAlbedo(diffuse, kSnowTint, kSnowBand, kSnowBandSpread); }
glm::vec3 mossAlbedo(glm::vec3 diffuse) { return bandAlbedo(diffuse, kMossTint, kGrassBand, kMossBandSpread); }
glm::vec3 iceAlbedo(glm::vec3 diffuse, glm::vec3 tangentNormal) {
  float cracks = smoothStep(kIceCrackBend.low, kIceCrackBend.high, glm::length(glm::vec2(tangentNormal)));
  float value = lerp(kOceanIceBand.low, kOceanIceBand.high, clamp01(detailMask(diffuse) * kIceBandSpread + cracks));
  return kIceTint / reflectance(kIceTint) * value;
}

float frostMask(float frostMap, float frostLevel) {
  float exponent = lerp(0.f, kFrostExponentMax, 1.f - clamp01(frostLevel));
  return std::pow(std::max(1.f - clamp01(frostMap), kMinFrostBase), exponent) * clamp01(frostLevel * kFrostFadeIn);
}

float puddleMask(glm::vec3 normal, float noise, float puddleLevel) {
  float flat = smoothStep(kCosPuddleMaxSlope, kCosPuddleFullSlope, glm::dot(normal, kUp));
  float shaped = smoothStep(0.5f - kPuddleEdge, 0.5f + kPuddleEdge, noise + puddleLevel - 0.5f);
  return flat * shaped;
}

float skyExposure(float pointHeight, float occluderHeight) {
  return 1.f - smoothStep(pointHeight + kShelterClearance, pointHeight + kShelterFull, occluderHeight);
}

glm::vec3 noiseRelief(glm::vec3 position, float height, float amplitude, glm::vec3 normal, glm::vec4 tangent) {
  float hx = noiseAt(position + glm::vec3(kReliefStep, 0.f, 0.f)).x;
  float hz = noiseAt(position + glm::vec3(0.f, 0.f, kReliefStep)).x;
  glm::vec3 slope = glm::vec3(hx - height, 0.f, hz - height) * (amplitude / kReliefStep);
  glm::vec3 t(tangent);
  glm::vec3 b = glm::cross(normal, t) * tangent.w;
  return {-glm::dot(slope, t), -glm::dot(slope, b), 1.f};
}

float filteredSkyExposure(const std::vector<float>& heights, int resolution, glm::vec2 uv, float pointHeight) {
  if (resolution <= 0 || heights.size() != static_cast<std::size_t>(resolution) * resolution) return 1.f;
  float x = uv.x * resolution - 0.5f, y = uv.y * resolution - 0.5f;
  float fx = std::floor(x), fy = std::floor(y);
  auto open = [&](int i, int j) {
    i = std::clamp(i, 0, resolution - 1);
    j = std::clamp(j, 0, resolution - 1);
    return skyExposure(pointHeight, heights[static_cast<std::size_t>(j) * resolution + i]);
  };
  int i = static_cast<int>(fx), j = static_cast<int>(fy);
  float ax = x - fx, ay = y - fy;
  float top = lerp(open(i, j), open(i + 1, j), ax);
  float bottom = lerp(open(i, j + 1), open(i + 1, j + 1), ax);
  return lerp(top, bottom, ay);
}


namespace {
glm::vec3 toVec3(const std::array<float, 3>& a) { return {a[0], a[1], a[2]}; }
glm::vec2 toVec2(const std::array<float, 2>& a) { return {a[0], a[1]}; }

// A term of eq. 3.1 under its switch: f when on (1), `neutral` when off (0), blended in
// between (a slope blend's terms; wg_switched_term).
float switchedTerm(float on, float f, float neutral) { return lerp(neutral, f, on); }

// Eq. 3.1 with the shape's switches: a switched-off factor counts as 1, and so does its
// weight (w1 = 2 balances a typical f_sun of 0.5, w3 = 2 a mid height; without the term
// the balance goes too); a switched-off sum term counts as 0.
float shapedPrediction(const FrameState& frame, glm::vec3 normal, glm::vec3 detailNormal, glm::vec3 position,
                       float terrain, float windFlow, const SnowShape& shape) {
  glm::vec4 weights = shape.weights;
  const glm::vec4& on = shape.terms;
  weights.x = switchedTerm(on.y, weights.x, 1.f);
  weights.z = switchedTerm(on.z, weights.z, 1.f);
  float inc = switchedTerm(on.x, inclination(normal, detailNormal, shape.inclinationIntensity), 1.f);
  float sun = switchedTerm(on.y, sunFacing(normal, toVec3(frame.sunDirection), frame.sunMelt), 1.f);
  float h = switchedTerm(on.z, height(position.y, shape.minHeight, shape.maxHeight), 1.f);
  float wind = switchedTerm(on.w, windFromFlow(normal, toVec2(frame.windDirection), windFlow, frame.windIntensity), 0.f);
  return prediction(inc, sun, h, terrain, wind, weights);
}
}  // namespace

float snowCoverage(const FrameState& frame, glm::vec3 normal, glm::vec3 detailNormal, glm::vec3 position,
                   glm::vec3 diffuse, float terrain, float windFlow, float exposure, const SnowShape& shape, float noise,
                   float patchNoise) {
  float level = clamp01(frame.snowLevel) * clamp01(exposure);
  float fp = shapedPrediction(frame, normal, detailNormal, position, terrain, windFlow, shape);
  float settling = transition(0.5f * noise + 0.5f * (1.f - detailMask(diffuse)), fp * level);
  float melting = smoothStep(0.f, kWetTemperatureRamp, frame.temperature);
  return lerp(settling, thawPatches(noise, patchNoise, fp * level), melting);
}

glm::vec3 snowOffset(const FrameState& frame, glm::vec3 normal, glm::vec3 position, float windFlow, float exposure,
                     const SnowShape& shape, float maxSnowHeight, float noise) {
  float level = clamp01(frame.snowLevel) * clamp01(exposure);
  float fp = shapedPrediction(frame, normal, normal, position, 0.f, windFlow, shape);
  return snowDisplacement(noise, fp * level, maxSnowHeight, normal);
}

float mossCoverage(const FrameState& frame, glm::vec3 normal, glm::vec3 position, glm::vec3 diffuse,
                   const SnowShape& shape, float noise) {
  float level = clamp01(frame.mossLevel);
  // Least sun (eq. 3.5 read for moss) and low ground (eq. 3.9), weighted as eq. 3.1's
  // w1 and w3; tops and sides alike, but not overhangs.
  float shade = sunShade(normal, toVec3(frame.sunDirection), frame.sunMelt);
  float low = heightInverted(position.y, shape.minHeight, shape.maxHeight);
  float facing = clamp01(1.f + kMossOverhangRamp * glm::dot(normal, kUp));
  float predicted = clamp01(shape.weights.x * shade * shape.weights.z * low) * facing;
  return transition(0.5f * noise + 0.5f * (1.f - detailMask(diffuse)), predicted * level);
}

float puddleCoverage(const FrameState& frame, glm::vec3 normal, float noise, float exposure) {
  float level = clamp01(frame.puddleLevel) * clamp01(exposure);
  return (level > 0.f ? 1.f : 0.f) * puddleMask(normal, noise, level);  // the mask alone is not 0 at level 0
}

float puddleIce(const FrameState& frame) {
  return std::max(clamp01(frame.frostLevel), 1.f - smoothStep(0.f, kWetTemperatureRamp, frame.temperature));
}

float frostCoverage(const FrameState& frame, float frostMap, float noise) {
  return transition(noise, frostMask(frostMap, frame.frostLevel));
}

float hoarfrostCoverage(const FrameState& frame, float noise, float exposure) {
  float level = clamp01(frame.frostLevel) * clamp01(exposure);
  return transition(noise, level);
}

}  // namespace wg::weather
