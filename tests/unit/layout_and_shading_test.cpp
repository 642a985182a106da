// std140 layout of the interface blocks, and eq. 2.1-2.5 against hand values.
#include <gtest/gtest.h>

#include <cmath>

#include "compiler/material_interface.hpp"
#include "nodes/pbr_shading.hpp"

namespace wg {
namespace {

TEST(Std140Layout, FollowsBaseAlignmentRules) {
  UniformBlock b;
  b.members = {{"f", "f", InterfaceType::Float}, {"v3", "v3", InterfaceType::Vec3}, {"g", "g", InterfaceType::Float},
               {"v2", "v2", InterfaceType::Vec2}, {"m", "m", InterfaceType::Mat4}, {"u", "u", InterfaceType::Uint}};
  layoutStd140(b);
  EXPECT_EQ(b.members[0].offset, 0u);
  EXPECT_EQ(b.members[1].offset, 16u);  // vec3 aligns to 16
  EXPECT_EQ(b.members[2].offset, 28u);  // a float packs after a vec3
  EXPECT_EQ(b.members[3].offset, 32u);  // vec2 aligns to 8
  EXPECT_EQ(b.members[4].offset, 48u);  // mat4 aligns to 16
  EXPECT_EQ(b.members[5].offset, 112u);
  EXPECT_EQ(b.size, 128u);  // rounded up to 16
}

TEST(Std140Layout, FrameBlockHasNoHoles) {
  UniformBlock frame = frameBlock();
  std::uint32_t end = 0;
  for (const auto& m : frame.members) {
    EXPECT_EQ(m.offset, end) << m.name;
    end = m.offset + m.size;
  }
  EXPECT_EQ(frame.size % 16, 0u);
}

TEST(PbrShading, GgxDistributionEq23) {
  EXPECT_NEAR(ggxDistribution(1.f, 1.f), 1.f / kPi, 1e-6f);  // alpha = 1: uniform 1/pi
  // r = 0.5: alpha = 0.25, a2 = 0.0625, at NoH = 1: D = 1 / (pi a2) = 5.09296
  EXPECT_NEAR(ggxDistribution(1.f, 0.5f), 1.f / (kPi * 0.0625f), 1e-4f);
}

TEST(PbrShading, SchlickSmithEq24) {
  // k = (0.5 + 1)^2 / 8 = 0.28125; G1(0.5) = 0.5 / (0.5 * 0.71875 + 0.28125) = 0.780488
  EXPECT_NEAR(smithSchlickG1(0.5f, 0.28125f), 0.5f / (0.5f * 0.71875f + 0.28125f), 1e-6f);
  EXPECT_NEAR(smithSchlickG(0.5f, 0.5f, 0.5f), 0.780488f * 0.780488f, 1e-5f);
  EXPECT_NEAR(smithSchlickG(1.f, 1.f, 0.3f), 1.f, 1e-6f);
}

TEST(PbrShading, SphericalGaussianFresnelEq25) {
  EXPECT_NEAR(fresnelSchlickSG(0.04f, 0.f), 1.f, 1e-6f);  // grazing: total reflection
  // Normal incidence: F0 + (1 - F0) 2^(-12.53789) = 0.04 + 0.96 * 1.6812e-4
  EXPECT_NEAR(fresnelSchlickSG(0.04f, 1.f), 0.04f + 0.96f * std::exp2(-12.53789f), 1e-7f);
  // Close to Schlick's (1 - VoH)^5 at VoH = 0.5: 0.04 + 0.96/32 = 0.07
  EXPECT_NEAR(fresnelSchlickSG(0.04f, 0.5f), 0.07f, 0.004f);
}

TEST(PbrShading, BurleyDiffuseEq21) {
  // At normal incidence both lobes are 1; only the energy normalisation remains.
  EXPECT_NEAR(burleyDiffuseFactor(1.f, 1.f, 1.f, 1.f), 1.f / 1.51f, 1e-6f);
  EXPECT_NEAR(burleyDiffuseFactor(0.f, 1.f, 1.f, 1.f), 1.f, 1e-6f);
  // Grazing light, rough: FD90 = 0.5 + 2 * 1 * 1 = 2.5; light lobe = 2.5, view lobe = 1.
  EXPECT_NEAR(burleyDiffuseFactor(1.f, 0.f, 1.f, 1.f), 2.5f / 1.51f, 1e-5f);
}

TEST(PbrShading, MetallicWorkflowAndEnergy) {
  ShadingInputs in;
  in.baseColor = {1.f, 0.f, 0.f};
  in.metallic = 1.f;
  in.roughness = 1.f;
  in.ambient = {1.f, 1.f, 1.f};
  auto metal = shadeSurface(in);
  EXPECT_NEAR(metal[1], metal[2], 1e-6f);  // no diffuse: green = blue = F0 of 0 only
  in.metallic = 0.f;
  auto dielectric = shadeSurface(in);
  EXPECT_GT(dielectric[0], metal[0] * 0.5f);  // diffuse red plus ambient
  // White Lambert-like surface under unit sun straight on: radiance stays below 1/pi * 1.1.
  ShadingInputs white;
  white.baseColor = {1.f, 1.f, 1.f};
  white.roughness = 1.f;
  white.specular = 0.f;
  auto w = shadeSurface(white);
  EXPECT_LT(w[0], 1.f / kPi * 1.1f);
  EXPECT_GT(w[0], 0.f);
}

// Environment reflection: a chrome mirror shows the sky instead of black, and a wet
// (smooth) dielectric at a grazing view reflects more of it than a dry (rough) one.
TEST(PbrShading, SkyReflectionShowsOnMetalsAndWetGround) {
  ShadingInputs chrome;
  chrome.baseColor = {0.95f, 0.95f, 0.95f};
  chrome.metallic = 1.f;
  chrome.roughness = 0.05f;
  chrome.toSun = {0.f, -1.f, 0.f};  // no sun: the sky alone
  chrome.reflected = {0.4f, 0.45f, 0.55f};
  EXPECT_GT(shadeSurface(chrome)[2], 0.45f);
  chrome.reflected = {0.f, 0.f, 0.f};
  EXPECT_LT(shadeSurface(chrome)[2], 1e-6f);  // black without the sky, as before
  ShadingInputs ground;
  ground.baseColor = {0.3f, 0.3f, 0.3f};
  ground.toViewer = {0.f, 0.1f, 0.995f};
  ground.toSun = {0.f, -1.f, 0.f};
  ground.reflected = {0.6f, 0.6f, 0.6f};
  ground.roughness = 0.9f;
  float dry = shadeSurface(ground)[0];
  ground.baseColor = {0.15f, 0.15f, 0.15f};  // eq. 3.16: wet ground is darker...
  ground.roughness = 0.05f;                   // ...and smoother (eq. 3.17)
  EXPECT_GT(shadeSurface(ground)[0], dry);
}

TEST(PbrShading, EnvironmentBrdfIsThePublishedFit) {
  auto [scale, bias] = environmentBrdf(0.f, 1.f);  // smooth, head-on: F0 alone
  EXPECT_NEAR(scale + bias * 0.f, 1.f, 0.03f);
  EXPECT_NEAR(bias, 0.f, 0.01f);
  auto [roughScale, roughBias] = environmentBrdf(1.f, 0.5f);
  EXPECT_LT(roughScale, 0.6f);
  EXPECT_GT(roughScale + roughBias, 0.f);
}

}  // namespace
}  // namespace wg
