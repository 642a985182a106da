// The UE4 shading model of seed 000, eq. 2.1-2.5, as CPU functions (for tests and the
// CPU evaluator) and as shader library text for GLSL and HLSL.
#pragma once
#include <array>

#include "nodes/op_definition.hpp"

namespace wg {

inline constexpr float kPi = 3.14159265358979f;
// Roughness below this makes GGX a near-delta: clamp so mirror-like puddles (roughness
// ~0) keep a finite, stable highlight.
inline constexpr float kMinShadingRoughness = 0.02f;

// Eq. 2.1 (Burley) without baseColor/pi: the two Fresnel-like retro-reflection lobes,
// with FD90 = 0.5 + 2 r cos^2(theta_d), times the energy normalisation lerp(1, 1/1.51, r).
float burleyDiffuseFactor(float roughness, float NoL, float NoV, float LoH);
// Eq. 2.3: GGX/Trowbridge-Reitz NDF with alpha = roughness^2.
float ggxDistribution(float NoH, float roughness);
// Eq. 2.4: Schlick-Smith G with k = (roughness + 1)^2 / 8, G = G1(l) G1(v).
float smithSchlickG1(float NoX, float k);
float smithSchlickG(float NoL, float NoV, float roughness);
// Eq. 2.5: Schlick Fresnel with the spherical-Gaussian power.
float fresnelSchlickSG(float f0, float VoH);

struct ShadingInputs {
  std::array<float, 3> baseColor{0.5f, 0.5f, 0.5f};
  float metallic = 0.f, roughness = 0.5f, specular = 0.5f, ambientOcclusion = 1.f;
  std::array<float, 3> emissive{0.f, 0.f, 0.f};
  std::array<float, 3> normal{0.f, 1.f, 0.f};  // world space, unit
  std::array<float, 3> toViewer{0.f, 1.f, 0.f};
  std::array<float, 3> toSun{0.f, 1.f, 0.f};
  std::array<float, 3> sunRadiance{1.f, 1.f, 1.f};  // colour * intensity
  std::array<float, 3> ambient{0.f, 0.f, 0.f};      // the sky's irradiance / pi at the normal (wg_sky_irradiance)
  std::array<float, 3> reflected{0.f, 0.f, 0.f};    // the prefiltered sky along the reflection (wg_sky_reflection)
};
// Eq. 2.2 Cook-Torrance specular plus Burley diffuse under one sun and the sky's diffuse light,
// metallic workflow (diffuse = base (1 - m), F0 = lerp(0.08 specular, base, m)), plus
// the sky's reflection by the split sum.
std::array<float, 3> shadeSurface(const ShadingInputs& in);
// wg_tonemap on the CPU, one channel: Narkowicz's ACES fit after the exposure.
float toneMapped(float linear, float exposure);
// The split sum's DFG term (Karis's analytic fit): F0 scale and bias.
std::array<float, 2> environmentBrdf(float roughness, float NoV);
// The sky's zenith colour under the weather: wg_sky_tint, for the background.
std::array<float, 3> skyTint(const std::array<float, 3>& skyColor, float precipitation, float windIntensity);

extern const ShaderLibrary kPbrShadingLibrary;

}  // namespace wg
