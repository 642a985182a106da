#include "host/distance_haze_pass.hpp"

#include <stdexcept>
#include <string>

#include "host/material_resources.hpp"
#include "host/sky_shader_text.hpp"
#include "vulkan/compute_barriers.hpp"
#include "vulkan/runtime_shader.hpp"

namespace wg {

namespace {
// 128 bytes: the push-constant size every Vulkan device offers.
struct HazeConstants {
  glm::mat4 clipToWorld;    // inverse view-projection: each pixel's view ray
  glm::vec4 sun;            // towards the sun (xyz, unit), its intensity
  glm::vec4 sky;            // the sky's zenith colour (rgb, linear), ambient intensity
  glm::vec4 weather;        // precipitation, wind intensity, tone exposure, -
  glm::vec4 range;          // near, far, extinction distance, where the horizon fade starts (m)
};
static_assert(sizeof(HazeConstants) == 128);

// The sky the surfaces reflect (wg_sky of the shading library, the same text), drawn
// where nothing was, with the sun's disc and its glow fading as the sky turns overcast;
// surfaces are hazed towards that sky's horizon in their direction (Beer-Lambert:
// 1 - exp(-d / distance), raised to 1 towards the far plane), so there is no seam.
constexpr std::string_view kHazeMain = R"(
void main() {
  ivec2 size = imageSize(Colour);
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, size))) return;
  vec2 ndc = (vec2(p) + 0.5) / vec2(size) * 2.0 - 1.0;
  vec4 nearPoint = haze.clipToWorld * vec4(ndc, 0.0, 1.0), farPoint = haze.clipToWorld * vec4(ndc, 1.0, 1.0);
  vec3 d = normalize(farPoint.xyz / farPoint.w - nearPoint.xyz / nearPoint.w);
  // Below kHorizonY the background is the horizon's colour: past the far plane there is
  // no ground to show, and haze tends to the same colour, so they meet without a seam.
  vec3 background = normalize(vec3(d.x, max(d.y, kHorizonY), d.z));
  vec3 horizon = wg_tonemap(wg_sky(normalize(vec3(d.x, kHorizonY, d.z) + vec3(1e-6, 0.0, 0.0))));
  float depth = texelFetch(sampler2D(SceneDepth, DepthSampler), p, 0).r;
  if (depth >= 1.0) {
    // The depth is one sample's (the multisampled resolve keeps sample 0): a pixel on
    // a silhouette may read as sky yet hold surface in its other samples. Haze it as
    // its nearest neighbour; only where all nine are sky is the sky drawn.
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx)
        depth = min(depth, texelFetch(sampler2D(SceneDepth, DepthSampler), clamp(p + ivec2(dx, dy), ivec2(0), size - 1), 0).r);
    if (depth >= 1.0) {
      float clear = 1.0 - clamp(frame_precipitation * 1.5, 0.0, 1.0);
      float toSun = dot(d, haze.sun.xyz), above = smoothstep(-0.01, 0.01, d.y);
      float disc = smoothstep(kSunDiscCos - 2e-5, kSunDiscCos + 2e-5, toSun);
      float glow = 0.6 * pow(max(toSun, 0.0), 400.0) + 0.12 * pow(max(toSun, 0.0), 12.0);
      vec3 sun = frame_sunColor * haze.sun.w * (disc * kSunDiscRadiance + glow) * clear * above;
      imageStore(Colour, p, vec4(wg_tonemap(wg_sky(background) + sun), 1.0));
      return;
    }
  }
  float n = haze.range.x, f = haze.range.y;
  float metres = n * f / (f - depth * (f - n));
  float amount = max(1.0 - exp(-metres / haze.range.z), smoothstep(haze.range.w, f, metres));
  vec4 c = imageLoad(Colour, p);
  imageStore(Colour, p, vec4(mix(c.rgb, horizon, amount), c.a));
}
)";

// The pass's shader: its bindings, the frame names wg_sky reads bound to the push
// constants, the shading library's sky functions, then main.
std::string hazeShader(const glm::vec3& sunColor) {
  std::string text = R"(#version 440
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;
layout(push_constant) uniform Haze { mat4 clipToWorld; vec4 sun; vec4 sky; vec4 weather; vec4 range; } haze;
layout(set = 0, binding = 0, rgba16f) uniform image2D Colour;
layout(set = 0, binding = 1) uniform texture2D SceneDepth;
layout(set = 0, binding = 2) uniform sampler DepthSampler;
#define frame_exposure haze.weather.z
)";
  text += "const vec3 frame_sunColor = vec3(" + std::to_string(sunColor.r) + ", " + std::to_string(sunColor.g) + ", " +
          std::to_string(sunColor.b) + ");\n";
  // The sun's angular radius is 0.27 degrees; drawn at 0.6 so that it reads in a
  // 480-pixel-wide frame. Its radiance saturates the tone curve: a white disc.
  text += "const float kSunDiscCos = 0.99994516;\nconst float kSunDiscRadiance = 40.0;\n";
  // Just above wg_sky's horizon edge (0.04), where the sky is all horizon.
  text += "const float kHorizonY = 0.05;\n";
  text += skyLibraryText("haze", {"wg_sky", "wg_tonemap"});
  text += kHazeMain;
  return text;
}
}  // namespace

DistanceHazePass::DistanceHazePass(vk::Context& ctx, const glm::vec3& sunColor) : ctx_(ctx) {
  auto module = vk::compileRuntimeShader(hazeShader(sunColor), vk::RuntimeStage::Compute, "sky and distance haze");
  set_ = std::make_unique<vk::ReflectedDescriptorSet>(ctx_, std::vector{module.interface}, VK_SHADER_STAGE_COMPUTE_BIT);
  if (set_->pushConstantBytes() != sizeof(HazeConstants))
    throw std::runtime_error("haze shader: push constants are " + std::to_string(set_->pushConstantBytes()) + " bytes");
  depthSampler_ = createSampler(ctx_, "clamp", "nearest");
  set_->bindSampler("DepthSampler", depthSampler_.get());
  module_ = vk::createShaderModule(ctx_, module.words);
  pipeline_ = vk::createComputePipeline(ctx_, module_.get(), set_->pipelineLayout());
  localSize_[0] = module.interface.localSize[0];
  localSize_[1] = module.interface.localSize[1];
}

DistanceHazePass::~DistanceHazePass() { vkDeviceWaitIdle(ctx_.device()); }

void DistanceHazePass::record(const ColourPassTargets& t, const FrameState& frame, const HazeSettings& settings) {
  const vk::Image2D& colour = *t.colour;
  std::uint32_t w = colour.width(), h = colour.height();
  set_->bindImage("Colour", colour.view(), VK_IMAGE_LAYOUT_GENERAL);
  set_->bindImage("SceneDepth", t.depth->view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
  vk::Image2D::transition(t.cmd, colour.handle(), VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                          VK_IMAGE_LAYOUT_GENERAL);
  vk::Image2D::transition(t.cmd, t.depth->handle(), VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
                          VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
  const SkyInputs sky = skyInputs(frame);
  const HazeConstants c{glm::inverse(t.viewProjection),
                        {frame.sunDirection[0], frame.sunDirection[1], frame.sunDirection[2], frame.sunIntensity},
                        sky.sky,
                        {sky.weather.x, sky.weather.y, frame.exposure, 0.f},
                        {t.nearPlane, t.farPlane, settings.distance, settings.horizonFrom * t.farPlane}};
  VkDescriptorSet set = set_->set();
  vkCmdBindPipeline(t.cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_.get());
  vkCmdBindDescriptorSets(t.cmd, VK_PIPELINE_BIND_POINT_COMPUTE, set_->pipelineLayout(), 0, 1, &set, 0, nullptr);
  vkCmdPushConstants(t.cmd, set_->pipelineLayout(), VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof c, &c);
  vkCmdDispatch(t.cmd, (w + localSize_[0] - 1) / localSize_[0], (h + localSize_[1] - 1) / localSize_[1], 1);
  vk::computeToComputeBarrier(t.cmd);
  vk::Image2D::transition(t.cmd, t.depth->handle(), VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                          VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL);
  vk::Image2D::transition(t.cmd, colour.handle(), VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_GENERAL,
                          VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
}

}  // namespace wg
