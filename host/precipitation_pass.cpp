#include "host/precipitation_pass.hpp"

#include <cmath>
#include <stdexcept>

#include "nodes/pbr_shading.hpp"
#include "host/material_resources.hpp"
#include "host/precipitation_shaders.hpp"
#include "vulkan/runtime_shader.hpp"

namespace wg {

namespace {
constexpr std::uint32_t kVerticesPerParticle = 6;
// The GPU derives positions from the time; wrapping it keeps float positions precise
// (at most ~10 km of travel) at the cost of a jump once every ten simulated minutes.
constexpr double kTimeWrap = 600.0;

// Large wet flakes of heavy snowfall, 1-2 cm across (radius +-30 % per flake); rain
// streaks 6 mm wide, a drop of 2-4 mm widened by its own blur. The camera's exposure
// sets the motion blur: a short one keeps flakes round in light wind and draws them as
// dashes in a blizzard; a longer one draws rain as the streaks the eye sees.
constexpr float kFlakeRadius = 0.007f, kDropRadius = 0.003f;  // m
constexpr float kSnowExposure = 1.f / 250.f, kRainExposure = 1.f / 25.f;  // s
// Thinner than this on screen (half-width, px) a particle is drawn this wide and
// correspondingly fainter.
constexpr float kLeastFlakeWidth = 0.8f, kLeastStreakWidth = 0.5f;
constexpr float kNearFade = 0.4f;  // m: nothing closer; full from twice this
// Depth over which a particle fades into the surface behind it (m).
constexpr float kSnowSoftness = 0.5f, kRainSoftness = 0.3f;

// Snowflakes: white (albedo 0.9), thin tumbling discs lit from both sides, so the sun
// reaches them at the mean |cos| of random orientations, 1/2; plus the sky. Raindrops
// are half transparent: faint streaks a little brighter than the sky they refract,
// with a glint of the sun.
constexpr float kSnowAlbedo = 0.9f, kFlakeSunFactor = 0.5f, kSnowOpacity = 0.9f;
constexpr float kRainSky = 1.3f, kRainSun = 0.12f, kRainOpacity = 0.5f;

// std140; mirrors `Precipitation` in precipitation_shaders.cpp.
struct PrecipitationBlock {
  glm::mat4 viewProjection;
  glm::vec4 eyeTime;
  glm::vec4 motion;
  glm::vec4 volume;
  glm::vec4 screen;
  glm::vec4 depthRange;
  glm::vec4 snowColour;
  glm::vec4 rainColour;
  glm::vec4 shutter;
  glm::uvec4 counts;
};
static_assert(sizeof(PrecipitationBlock) == 64 + 9 * 16, "std140 layout of the Precipitation block");

// The materials' tone curve (wg_tonemap).
glm::vec3 toneMappedColour(glm::vec3 c, float exposure) {
  return {toneMapped(c.r, exposure), toneMapped(c.g, exposure), toneMapped(c.b, exposure)};
}
}  // namespace

PrecipitationLook precipitationLook(const PrecipitationLight& light) {
  glm::vec3 snow = kSnowAlbedo * (light.sunRadiance * (kFlakeSunFactor / kPi) + light.skyRadiance);
  glm::vec3 rain = kRainSky * light.skyRadiance + kRainSun * light.sunRadiance;
  return {glm::vec4(toneMappedColour(snow, light.exposure), kSnowOpacity), glm::vec4(toneMappedColour(rain, light.exposure), kRainOpacity)};
}

PrecipitationPass::PrecipitationPass(vk::Context& ctx)
    : ctx_(ctx), overlay_(ctx.device()), block_(ctx, sizeof(PrecipitationBlock), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT) {
  auto vertex = vk::compileRuntimeShader(precipitationVertexSource(), vk::RuntimeStage::Vertex, "precipitation vertex");
  auto fragment = vk::compileRuntimeShader(precipitationFragmentSource(), vk::RuntimeStage::Fragment, "precipitation fragment");
  set_ = std::make_unique<vk::ReflectedDescriptorSet>(ctx_, std::vector{vertex.interface, fragment.interface},
                                                      VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT);
  set_->bindBuffer("Precipitation", block_);
  depthSampler_ = createSampler(ctx_, "clamp", "nearest");
  set_->bindSampler("DepthSampler", depthSampler_.get());
  vertexModule_ = vk::createShaderModule(ctx_, vertex.words);
  fragmentModule_ = vk::createShaderModule(ctx_, fragment.words);
  pipeline_ = overlay_.pipeline(vertexModule_.get(), fragmentModule_.get(), set_->pipelineLayout());
}

PrecipitationPass::~PrecipitationPass() { vkDeviceWaitIdle(ctx_.device()); }

void PrecipitationPass::record(const ColourPassTargets& t, const PrecipitationField& field, const PrecipitationLight& light,
                               double seconds) {
  if (field.total() == 0) return;
  const float width = float(t.colour->width()), height = float(t.colour->height());
  // Pixels per metre at 1 m: the view-projection's y row is the projection's y scale
  // times the view's (unit) up row.
  const glm::vec3 yRow(t.viewProjection[0][1], t.viewProjection[1][1], t.viewProjection[2][1]);
  const PrecipitationLook look = precipitationLook(light);
  PrecipitationBlock b{};
  b.viewProjection = t.viewProjection;
  b.eyeTime = glm::vec4(t.eye, float(std::fmod(std::isfinite(seconds) ? seconds : 0.0, kTimeWrap)));
  b.motion = glm::vec4(field.wind[0], field.wind[1], field.snowFallSpeed, field.rainFallSpeed);
  b.volume = glm::vec4(field.radius, kNearFade, kFlakeRadius, kDropRadius);
  b.screen = glm::vec4(width, height, 0.5f * height * glm::length(yRow), 0.f);
  b.depthRange = glm::vec4(t.nearPlane, t.farPlane, kSnowSoftness, kRainSoftness);
  b.snowColour = look.snow;
  b.rainColour = look.rain;
  b.shutter = glm::vec4(kSnowExposure, kRainExposure, kLeastFlakeWidth, kLeastStreakWidth);
  b.counts = glm::uvec4(field.snowflakes, field.total(), 0u, 0u);
  block_.write(&b, sizeof b);
  set_->bindImage("SceneDepth", t.depth->view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
  overlay_.begin(t);
  VkDescriptorSet set = set_->set();
  vkCmdBindPipeline(t.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_.get());
  vkCmdBindDescriptorSets(t.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, set_->pipelineLayout(), 0, 1, &set, 0, nullptr);
  vkCmdDraw(t.cmd, kVerticesPerParticle, field.total(), 0, 0);
  overlay_.end(t);
}

}  // namespace wg
