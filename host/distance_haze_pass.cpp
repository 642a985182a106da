#include "host/distance_haze_pass.hpp"

#include <stdexcept>
#include <string>

#include "host/material_resources.hpp"
#include "vulkan/compute_barriers.hpp"
#include "vulkan/runtime_shader.hpp"

namespace wg {

namespace {
struct HazeConstants {
  glm::vec4 colour;  // rgb, unused
  glm::vec4 range;   // near, far, extinction distance, where the horizon fade starts (m)
  std::int32_t size[2];
};

// Depth to metres as the puffs do (the inverse of the zero-to-one projection); the
// haze is 1 - exp(-d / distance) (Beer-Lambert), raised to 1 towards the far plane.
constexpr std::string_view kHaze = R"(#version 450
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;
layout(push_constant) uniform Haze { vec4 colour; vec4 range; ivec2 size; } haze;
layout(set = 0, binding = 0, rgba32f) uniform image2D Colour;
layout(set = 0, binding = 1) uniform texture2D SceneDepth;
layout(set = 0, binding = 2) uniform sampler DepthSampler;
void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, haze.size))) return;
  float depth = texelFetch(sampler2D(SceneDepth, DepthSampler), p, 0).r;
  if (depth >= 1.0) {
    // The depth is one sample's (the multisampled resolve keeps sample 0): a pixel on
    // a silhouette may read as sky yet hold surface in its other samples. Haze it as
    // its nearest neighbour; the sky itself, a blend towards its own colour, keeps it.
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx)
        depth = min(depth, texelFetch(sampler2D(SceneDepth, DepthSampler), clamp(p + ivec2(dx, dy), ivec2(0), haze.size - 1), 0).r);
    if (depth >= 1.0) return;  // the sky itself
  }
  float n = haze.range.x, f = haze.range.y;
  float metres = n * f / (f - depth * (f - n));
  float amount = max(1.0 - exp(-metres / haze.range.z), smoothstep(haze.range.w, f, metres));
  vec4 c = imageLoad(Colour, p);
  imageStore(Colour, p, vec4(mix(c.rgb, haze.colour.rgb, amount), c.a));
}
)";
}  // namespace

DistanceHazePass::DistanceHazePass(vk::Context& ctx) : ctx_(ctx) {
  auto module = vk::compileRuntimeShader(kHaze, vk::RuntimeStage::Compute, "distance haze");
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

void DistanceHazePass::record(const ColourPassTargets& t, const HazeSettings& settings) {
  const vk::Image2D& colour = *t.colour;
  std::uint32_t w = colour.width(), h = colour.height();
  set_->bindImage("Colour", colour.view(), VK_IMAGE_LAYOUT_GENERAL);
  set_->bindImage("SceneDepth", t.depth->view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
  vk::Image2D::transition(t.cmd, colour.handle(), VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                          VK_IMAGE_LAYOUT_GENERAL);
  vk::Image2D::transition(t.cmd, t.depth->handle(), VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
                          VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
  HazeConstants c{glm::vec4(settings.colour, 0.f),
                  {t.nearPlane, t.farPlane, settings.distance, settings.horizonFrom * t.farPlane},
                  {std::int32_t(w), std::int32_t(h)}};
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
