// The reference host's diffuse sky light (host/sky_light_builder.hpp): built from
// the weather's sky once per sky, never per frame, and what a rough dielectric shows.
#include <gtest/gtest.h>

#include <filesystem>

#include "backends/library_functions.hpp"
#include "backends/shader_syntax.hpp"
#include "compiler/debug_views.hpp"
#include "nodes/pbr_shading.hpp"
#include "vulkan/compute_barriers.hpp"
#include "vulkan/gpu_buffer.hpp"
#include "vulkan/reflected_descriptor_set.hpp"
#include "vulkan/runtime_shader.hpp"
#include "host/scene/preview_stand.hpp"
#include "process_support.hpp"
#include "render_support.hpp"

namespace wg::testing {
namespace {

namespace fs = std::filesystem;

#define REQUIRE_VULKAN() \
  if (!renderContext()) GTEST_SKIP() << "no Vulkan driver (install mesa-vulkan-drivers)"

constexpr float kAlbedo = 0.8f;

std::uint32_t viewId(std::string_view name) {
  for (const auto& v : kDebugViews)
    if (v.name == name) return v.id;
  throw std::logic_error("no debug view " + std::string(name));
}

// A white, fully rough dielectric without specular (F0 = 0): the sky's reflection adds
// at most its DFG bias, a quarter of a percent at roughness 1.
SceneRenderer roughWhiteStand(const TempDir& dir) {
  fs::path graph = dir.path() / "rough_white.json";
  writeFile(graph, R"({"name": "rough_white", "nodes": [],
    "output": {"baseColor": 0.8, "metallic": 0.0, "roughness": 1.0, "specular": 0.0}})");
  return SceneRenderer(*renderContext(), scene::previewStand(graph.string()), std::string(WG_SOURCE_DIR) + "/graphs");
}

RenderRequest sunlessFrame(const SceneRenderer& renderer, std::uint32_t width, std::uint32_t height) {
  RenderRequest r;
  r.camera = "front";
  r.width = width;
  r.height = height;
  r.weather = weatherFor(renderer.scene());
  r.weather.conditions.sunIntensity = 0.f;
  r.shadows = false;
  return r;
}

TEST(SkyIrradianceRender, RebuiltOnlyWhenTheSkyChanges) {
  REQUIRE_VULKAN();
  TempDir dir("sky-irradiance-builds");
  SceneRenderer renderer = roughWhiteStand(dir);
  RenderRequest r = sunlessFrame(renderer, 32, 18);
  r.debugView = viewId("albedo");
  renderer.render(r);
  EXPECT_EQ(renderer.skyLightBuilds(), 0u) << "AOVs do not read the sky";
  r.debugView = 0;
  renderer.render(r);
  renderer.render(r);
  EXPECT_EQ(renderer.skyLightBuilds(), 1u);
  r.weather.levels.snow = 0.5f;  // the ground changes, the sky does not
  r.weather.time = 600.0;
  renderer.render(r);
  EXPECT_EQ(renderer.skyLightBuilds(), 1u);
  const glm::vec3 clearUp = skyIrradianceAt(renderer.skyIrradiance(), {0.f, 1.f, 0.f});
  r.weather.conditions.precipitation = 0.8f;  // overcast
  renderer.render(r);
  EXPECT_EQ(renderer.skyLightBuilds(), 2u);
  expectNoValidationMessages();
  // A clear sky lights up-facing faces bluer than an overcast one, and any sky lights
  // them more than the ground below lights down-facing ones.
  const glm::vec3 overcastUp = skyIrradianceAt(renderer.skyIrradiance(), {0.f, 1.f, 0.f});
  EXPECT_GT(clearUp.b / clearUp.r, overcastUp.b / overcastUp.r * 1.2f);
  EXPECT_GT(overcastUp.g, 2.f * skyIrradianceAt(renderer.skyIrradiance(), {0.f, -1.f, 0.f}).g);
}

// wg_sky_irradiance evaluated on the GPU (the shading library's text, reading its nine
// coefficients from a buffer) at each of `normals`.
std::vector<glm::vec3> shaderIrradiance(const SkyIrradiance& sky, const std::vector<glm::vec3>& normals) {
  vk::Context& ctx = *renderContext();
  std::string text = R"(#version 440
layout(local_size_x = 32, local_size_y = 1, local_size_z = 1) in;
layout(std430, set = 0, binding = 0) readonly buffer Coefficients { vec4 coefficients[9]; };
layout(std430, set = 0, binding = 1) buffer Normals { vec4 normals[]; };
)";
  for (int i = 0; i < 9; ++i)
    text += "#define frame_skyIrradiance" + std::to_string(i) + " coefficients[" + std::to_string(i) + "]\n";
  for (const ReachedPiece& piece : reachedLibraryPieces(glslSyntax(), {&kPbrShadingLibrary}, {"wg_sky_irradiance"}))
    text += piece.text;
  text += R"(
void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i < uint(normals.length())) normals[i] = vec4(wg_sky_irradiance(normals[i].xyz), 0.0);
}
)";
  auto module = vk::compileRuntimeShader(text, vk::RuntimeStage::Compute, "wg_sky_irradiance test");
  vk::ReflectedDescriptorSet set(ctx, {module.interface}, VK_SHADER_STAGE_COMPUTE_BIT);
  vk::Buffer coefficients(ctx, 9 * sizeof(glm::vec4), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  vk::Buffer values(ctx, normals.size() * sizeof(glm::vec4), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  auto* c = static_cast<glm::vec4*>(coefficients.mapped());
  for (int i = 0; i < 9; ++i) c[i] = glm::vec4(sky.coefficients[i], 0.f);
  auto* v = static_cast<glm::vec4*>(values.mapped());
  for (std::size_t i = 0; i < normals.size(); ++i) v[i] = glm::vec4(normals[i], 0.f);
  set.bindBuffer("Coefficients", coefficients);
  set.bindBuffer("Normals", values);
  vk::UniqueShaderModule shader = vk::createShaderModule(ctx, module.words);
  vk::UniquePipeline pipeline = vk::createComputePipeline(ctx, shader.get(), set.pipelineLayout());
  ctx.submitAndWait([&](VkCommandBuffer cmd) {
    VkDescriptorSet handle = set.set();
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.get());
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, set.pipelineLayout(), 0, 1, &handle, 0, nullptr);
    vkCmdDispatch(cmd, static_cast<std::uint32_t>((normals.size() + 31) / 32), 1, 1);
    vk::computeToHostBarrier(cmd);
  });
  std::vector<glm::vec3> out;
  for (std::size_t i = 0; i < normals.size(); ++i) out.emplace_back(v[i]);
  return out;
}

// The shader's sum is the host's, coefficient by coefficient: each of nine skies has
// one coefficient set, so a term with the wrong polynomial or none shows.
TEST(SkyIrradianceRender, TheShadersIrradianceIsTheHosts) {
  REQUIRE_VULKAN();
  std::vector<glm::vec3> normals;
  for (const SkySample& s : cubeSkySamples(3)) normals.push_back(s.direction);
  for (std::size_t i = 0; i < 9; ++i) {
    SkyIrradiance sky;
    sky.coefficients[i] = glm::vec3(1.f, -0.5f, 0.25f);
    const std::vector<glm::vec3> gpu = shaderIrradiance(sky, normals);
    for (std::size_t k = 0; k < normals.size(); ++k) {
      const glm::vec3 cpu = skyIrradianceAt(sky, normals[k]);
      for (int c = 0; c < 3; ++c) ASSERT_NEAR(gpu[k][c], cpu[c], 1e-5f) << "coefficient " << i << ", normal " << k;
    }
  }
  expectNoValidationMessages();
}

// The issue's guard for the diffuse term: a rough dielectric does not change when the
// environment's reflection is taken away and its ambient is held at the sky's
// irradiance. With the sun off, every pixel of the sphere is its albedo times the sky's
// irradiance / pi at its normal, evaluated here from the coefficients the frame used.
// A constant ambient (the term this replaced) misses the sphere's underside by 40 %.
TEST(SkyIrradianceRender, ARoughDielectricIsItsAlbedoTimesTheSkysIrradiance) {
  REQUIRE_VULKAN();
  TempDir dir("sky-irradiance-rough");
  SceneRenderer renderer = roughWhiteStand(dir);
  RenderRequest r = sunlessFrame(renderer, 320, 180);
  r.onlyObject = "sphere";
  const RenderedFrame lit = renderer.render(r);
  const SkyIrradiance& sky = renderer.skyIrradiance();
  r.debugView = viewId("geometricNormal");
  const RenderedFrame normals = renderer.render(r);
  expectNoValidationMessages();
  auto inside = [&](int x, int y) {  // all four neighbours on the sphere: no resolved edge
    return isSurface(normals, x, y) && isSurface(normals, x - 1, y) && isSurface(normals, x + 1, y) &&
           isSurface(normals, x, y - 1) && isSurface(normals, x, y + 1);
  };
  int pixels = 0;
  float lowest = 1.f, highest = 0.f;
  for (int y = 1; y + 1 < int(normals.height); ++y)
    for (int x = 1; x + 1 < int(normals.width); ++x) {
      if (!inside(x, y)) continue;
      ++pixels;
      const glm::vec3 n = glm::normalize(glm::vec3(pixel(normals, x, y)));
      const glm::vec3 expected = kAlbedo * skyIrradianceAt(sky, n);
      const glm::vec4 got = pixel(lit, x, y);
      for (int c = 0; c < 3; ++c) {
        // The reflection's bias and the interpolated normals leave at most 0.003 here.
        ASSERT_NEAR(got[c], toneMapped(expected[c], 1.f), 0.006f) << "pixel " << x << "," << y << " channel " << c;
      }
      lowest = std::min(lowest, got.g);
      highest = std::max(highest, got.g);
    }
  EXPECT_GT(pixels, 400);
  EXPECT_GT(highest, lowest * 1.3f) << "the sphere's top sees the sky, its underside the ground";
}

}  // namespace
}  // namespace wg::testing
