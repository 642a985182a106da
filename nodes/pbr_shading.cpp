#include "nodes/pbr_shading.hpp"

#include <algorithm>
#include <cmath>

namespace wg {

namespace {
// UE4's energy normalisation of Burley diffuse (Lagarde & de Rousiers 2014): the
// retro-reflection can exceed 1, so scale by 1/1.51 at full roughness.
constexpr float kBurleyEnergyScale = 1.f / 1.51f;
// Spherical-Gaussian fit of (1 - VoH)^5 used by UE4 (eq. 2.5).
constexpr float kSgA = -5.55473f, kSgB = -6.98316f;
// UE4: F0 = 0.08 * specular, so the default specular 0.5 gives 0.04.
constexpr float kSpecularToF0 = 0.08f;
// Guards for n.v and the 4 (n.l)(n.v) denominator at grazing angles.
constexpr float kMinNoV = 1e-4f;

float pow5(float x) { return x * x * x * x * x; }
float dot3(const std::array<float, 3>& a, const std::array<float, 3>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
}  // namespace

float burleyDiffuseFactor(float roughness, float NoL, float NoV, float LoH) {
  float fd90 = 0.5f + 2.f * roughness * LoH * LoH;
  float lightScatter = 1.f + (fd90 - 1.f) * pow5(1.f - NoL);
  float viewScatter = 1.f + (fd90 - 1.f) * pow5(1.f - NoV);
  float energy = 1.f + (kBurleyEnergyScale - 1.f) * roughness;
  return lightScatter * viewScatter * energy;
}

float ggxDistribution(float NoH, float roughness) {
  float a = roughness * roughness;
  float a2 = a * a;
  float d = NoH * NoH * (a2 - 1.f) + 1.f;
  return a2 / (kPi * d * d);
}

float smithSchlickG1(float NoX, float k) { return NoX / (NoX * (1.f - k) + k); }

float smithSchlickG(float NoL, float NoV, float roughness) {
  float k = (roughness + 1.f) * (roughness + 1.f) / 8.f;
  return smithSchlickG1(NoL, k) * smithSchlickG1(NoV, k);
}

float fresnelSchlickSG(float f0, float VoH) {
  return f0 + (1.f - f0) * std::exp2((kSgA * VoH + kSgB) * VoH);
}

std::array<float, 3> skyTint(const std::array<float, 3>& skyColor, float precipitation, float windIntensity) {
  const std::array<float, 3> kOvercast{0.62f, 0.64f, 0.68f};
  float overcast = std::clamp(precipitation * 1.5f, 0.f, 1.f);
  std::array<float, 3> tint{};
  for (int c = 0; c < 3; ++c)
    tint[c] = (skyColor[c] + (kOvercast[c] - skyColor[c]) * overcast) * (1.f - 0.45f * overcast * windIntensity);
  return tint;
}

float toneMapped(float linear, float exposure) {
  float c = linear * exposure;
  return std::clamp((c * (2.51f * c + 0.03f)) / (c * (2.43f * c + 0.59f) + 0.14f), 0.f, 1.f);
}

std::array<float, 2> environmentBrdf(float roughness, float NoV) {
  const float r[4] = {roughness * -1.f + 1.f, roughness * -0.0275f + 0.0425f, roughness * -0.572f + 1.04f,
                      roughness * 0.022f - 0.04f};
  float a004 = std::min(r[0] * r[0], std::exp2(-9.28f * NoV)) * r[0] + r[1];
  return {-1.04f * a004 + r[2], 1.04f * a004 + r[3]};
}

std::array<float, 3> shadeSurface(const ShadingInputs& in) {
  float roughness = std::clamp(in.roughness, kMinShadingRoughness, 1.f);
  std::array<float, 3> h{in.toViewer[0] + in.toSun[0], in.toViewer[1] + in.toSun[1], in.toViewer[2] + in.toSun[2]};
  float hl = std::sqrt(std::max(dot3(h, h), 1e-12f));
  for (auto& c : h) c /= hl;
  float NoL = std::clamp(dot3(in.normal, in.toSun), 0.f, 1.f);
  float NoV = std::max(dot3(in.normal, in.toViewer), kMinNoV);
  float NoH = std::clamp(dot3(in.normal, h), 0.f, 1.f);
  float VoH = std::clamp(dot3(in.toViewer, h), 0.f, 1.f);
  float diffuseTerm = burleyDiffuseFactor(roughness, NoL, NoV, VoH) / kPi;
  float dg = ggxDistribution(NoH, roughness) * smithSchlickG(NoL, NoV, roughness) / std::max(4.f * NoL * NoV, kMinNoV);
  auto [scale, bias] = environmentBrdf(roughness, NoV);
  float ao = in.ambientOcclusion;
  float occlusion = std::clamp(std::pow(NoV + ao, std::exp2(-16.f * roughness - 1.f)) - 1.f + ao, 0.f, 1.f);
  std::array<float, 3> out{};
  for (int c = 0; c < 3; ++c) {
    float diffuseColor = in.baseColor[c] * (1.f - in.metallic);
    float f0 = kSpecularToF0 * in.specular + (in.baseColor[c] - kSpecularToF0 * in.specular) * in.metallic;
    float spec = dg * fresnelSchlickSG(f0, VoH);
    out[c] = (diffuseColor * diffuseTerm + spec) * in.sunRadiance[c] * NoL + in.ambient[c] * diffuseColor * ao +
             in.reflected[c] * (f0 * scale + bias) * occlusion + in.emissive[c];
  }
  return out;
}

const ShaderLibrary kPbrShadingLibrary = {
    "pbr_shading",
    R"(// Seed 000, eq. 2.1-2.5: the UE4 shading model.
float wg_pow5(const float x) { return x * x * x * x * x; }
// Eq. 2.1: Burley diffuse with FD90 = 0.5 + 2 r cos^2(theta_d), energy-normalised.
float wg_burley_diffuse(const float roughness, const float NoL, const float NoV, const float LoH) {
  float fd90 = 0.5 + 2.0 * roughness * LoH * LoH;
  float lightScatter = 1.0 + (fd90 - 1.0) * wg_pow5(1.0 - NoL);
  float viewScatter = 1.0 + (fd90 - 1.0) * wg_pow5(1.0 - NoV);
  return lightScatter * viewScatter * (1.0 + (0.66225166 - 1.0) * roughness);
}
// Eq. 2.3: GGX with alpha = roughness^2.
float wg_ggx(const float NoH, const float roughness) {
  float a = roughness * roughness;
  float a2 = a * a;
  float d = NoH * NoH * (a2 - 1.0) + 1.0;
  return a2 / (3.14159265 * d * d);
}
// Eq. 2.4: Schlick-Smith with k = (r + 1)^2 / 8.
float wg_smith_g(const float NoL, const float NoV, const float roughness) {
  float k = (roughness + 1.0) * (roughness + 1.0) / 8.0;
  return (NoL / (NoL * (1.0 - k) + k)) * (NoV / (NoV * (1.0 - k) + k));
}
// Eq. 2.5: spherical-Gaussian Schlick Fresnel.
vec3 wg_fresnel(const vec3 f0, const float VoH) {
  return f0 + (1.0 - f0) * exp2((-5.55473 * VoH - 6.98316) * VoH);
}
// Sun shadow: 2x2 percentage-closer filtering of the shadow map's depth. The normal
// offset and depth bias keep lit surfaces from shadowing themselves.
float wg_sun_shadow(const vec3 p, const vec3 n) {
  if (frame_shadowMapTexel <= 0.0) return 1.0;
  vec4 clip = frame_lightViewProjection * vec4(p + n * 0.04, 1.0);
  if (clip.w <= 0.0) return 1.0;
  vec3 ndc = clip.xyz / clip.w;
  vec2 uv = ndc.xy * 0.5 + 0.5;
  if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0))) || ndc.z > 1.0) return 1.0;
  float h = 0.5 * frame_shadowMapTexel;
  float depth = ndc.z - 0.0015;
  float lit = step(depth, texture(sampler2D(wg_sun_shadow_map, wg_sun_shadow_sampler), uv + vec2(-h, -h)).r);
  lit += step(depth, texture(sampler2D(wg_sun_shadow_map, wg_sun_shadow_sampler), uv + vec2(h, -h)).r);
  lit += step(depth, texture(sampler2D(wg_sun_shadow_map, wg_sun_shadow_sampler), uv + vec2(-h, h)).r);
  lit += step(depth, texture(sampler2D(wg_sun_shadow_map, wg_sun_shadow_sampler), uv + vec2(h, h)).r);
  return lit * 0.25;
}
// The reference host's sky, the environment its surfaces reflect: zenith frame_skyColor,
// a paler horizon and a dim ground; precipitation turns it overcast and a blizzard
// darkens it (wg_sky_tint, mirrored by skyTint on the CPU for the background).
vec3 wg_sky_tint() {
  float overcast = clamp(frame_precipitation * 1.5, 0.0, 1.0);
  return mix(frame_skyColor, vec3(0.62, 0.64, 0.68), overcast) * (1.0 - 0.45 * overcast * frame_windIntensity);
}
vec3 wg_sky(const vec3 d) {
  vec3 tint = wg_sky_tint() * frame_ambientIntensity;
  float luminance = dot(tint, vec3(0.2126, 0.7152, 0.0722));
  // A clear sky is deepest blue overhead and palest at the horizon.
  vec3 zenith = max(mix(vec3(luminance), tint, 2.5), vec3(0.0));
  vec3 horizon = mix(tint, vec3(luminance), 0.3) * 1.1;
  vec3 sky = mix(horizon, zenith, sqrt(clamp(d.y, 0.0, 1.0)));
  return mix(horizon * 0.35, sky, smoothstep(-0.04, 0.04, d.y));
}
// The split sum's first factor: wg_sky prefiltered with GGX of the roughness, from the
// host's cube map, one roughness per level (level = 5 roughness; host/sky_light_builder.hpp).
vec3 wg_sky_reflection(const vec3 r, const float roughness) {
  return textureLod(samplerCube(wg_sky_reflection_map, wg_sky_reflection_sampler), r, roughness * 5.0).rgb;
}
// The sky's diffuse light at normal n: its irradiance / pi from the 9 spherical-harmonic
// coefficients the host projects wg_sky onto (Ramamoorthi & Hanrahan 2001, eq. 13, y up;
// host/sky_irradiance.hpp). A sky of one radiance everywhere gives that radiance.
vec3 wg_sky_irradiance(const vec3 n) {
  return frame_skyIrradiance0.rgb + frame_skyIrradiance1.rgb * n.x + frame_skyIrradiance2.rgb * n.y +
         frame_skyIrradiance3.rgb * n.z + frame_skyIrradiance4.rgb * (n.x * n.y) +
         frame_skyIrradiance5.rgb * (n.y * n.z) + frame_skyIrradiance6.rgb * (3.0 * n.y * n.y - 1.0) +
         frame_skyIrradiance7.rgb * (n.x * n.z) + frame_skyIrradiance8.rgb * (n.z * n.z - n.x * n.x);
}
// The split sum's DFG term by Karis's analytic fit (UE4 mobile): F0 scale and bias.
vec2 wg_env_brdf(const float roughness, const float NoV) {
  vec4 r = roughness * vec4(-1.0, -0.0275, -0.572, 0.022) + vec4(1.0, 0.0425, 1.04, -0.04);
  float a004 = min(r.x * r.x, exp2(-9.28 * NoV)) * r.x + r.y;
  return vec2(-1.04, 1.04) * a004 + r.zw;
}
// Eq. 2.2 plus Burley diffuse, sun (times its shadow) and the sky's diffuse light at the
// normal, metallic workflow, and the sky's reflection (split sum, with Lagarde's
// specular occlusion from ao).
vec3 wg_shade(const vec3 baseColor, const float metallic, float roughness, const float specular, const float ao,
              const vec3 emissive, const vec3 N, const vec3 V, const float shadow) {
  roughness = clamp(roughness, 0.02, 1.0);
  vec3 L = frame_sunDirection;
  vec3 H = wg_safe_normalize(V + L);
  float NoL = clamp(dot(N, L), 0.0, 1.0);
  float NoV = max(dot(N, V), 1e-4);
  float NoH = clamp(dot(N, H), 0.0, 1.0);
  float VoH = clamp(dot(V, H), 0.0, 1.0);
  vec3 diffuseColor = baseColor * (1.0 - metallic);
  vec3 f0 = mix(vec3(0.08 * specular), baseColor, metallic);
  float dg = wg_ggx(NoH, roughness) * wg_smith_g(NoL, NoV, roughness) / max(4.0 * NoL * NoV, 1e-4);
  vec3 direct = (diffuseColor * (wg_burley_diffuse(roughness, NoL, NoV, VoH) / 3.14159265) + dg * wg_fresnel(f0, VoH));
  vec3 sun = frame_sunColor * frame_sunIntensity * shadow;
  vec3 sky = wg_sky_irradiance(N);
  vec2 dfg = wg_env_brdf(roughness, NoV);
  float occlusion = clamp(pow(NoV + ao, exp2(-16.0 * roughness - 1.0)) - 1.0 + ao, 0.0, 1.0);
  vec3 reflection = wg_sky_reflection(reflect(-V, N), roughness) * (f0 * dfg.x + dfg.y) * occlusion;
  return direct * sun * NoL + sky * diffuseColor * ao + reflection + emissive;
}
// Filmic tone curve (Narkowicz's ACES fit) so renders are viewable as 8-bit images.
vec3 wg_tonemap(vec3 c) {
  c *= frame_exposure;
  return clamp((c * (2.51 * c + 0.03)) / (c * (2.43 * c + 0.59) + 0.14), 0.0, 1.0);
}
)",
    {}};

}  // namespace wg
