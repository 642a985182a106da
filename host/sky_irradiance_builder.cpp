#include "host/sky_irradiance_builder.hpp"

#include <memory>
#include <stdexcept>
#include <string>

#include "vulkan/compute_barriers.hpp"
#include "vulkan/runtime_shader.hpp"

namespace wg {

namespace {
// wg_sky at roughness 0 (the radiance itself) towards each direction.
std::string skyRadianceShader() {
  std::string text = R"(#version 450
layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;
layout(push_constant) uniform Sky { vec4 sky; vec4 weather; } pc;
layout(std430, set = 0, binding = 0) readonly buffer Directions { vec4 directions[]; };
layout(std430, set = 0, binding = 1) writeonly buffer Radiance { vec4 radiance[]; };
)";
  text += skyLibraryText("pc", {"wg_sky"});
  text += R"(
void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= uint(directions.length())) return;
  radiance[i] = vec4(wg_sky(directions[i].xyz, 0.0), 1.0);
}
)";
  return text;
}
}  // namespace

SkyIrradianceBuilder::SkyIrradianceBuilder(vk::Context& ctx)
    : ctx_(ctx),
      samples_(cubeSkySamples(kFaceSize)),
      directions_(ctx, samples_.size() * sizeof(glm::vec4), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT),
      radiance_(ctx, samples_.size() * sizeof(glm::vec4), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT) {
  auto* directions = static_cast<glm::vec4*>(directions_.mapped());
  for (std::size_t i = 0; i < samples_.size(); ++i) directions[i] = glm::vec4(samples_[i].direction, 0.f);
  auto module = vk::compileRuntimeShader(skyRadianceShader(), vk::RuntimeStage::Compute, "sky irradiance");
  set_ = std::make_unique<vk::ReflectedDescriptorSet>(ctx_, std::vector{module.interface}, VK_SHADER_STAGE_COMPUTE_BIT);
  if (set_->pushConstantBytes() != sizeof(SkyInputs))
    throw std::runtime_error("sky irradiance shader: push constants are " + std::to_string(set_->pushConstantBytes()) +
                             " bytes");
  set_->bindBuffer("Directions", directions_);
  set_->bindBuffer("Radiance", radiance_);
  module_ = vk::createShaderModule(ctx_, module.words);
  pipeline_ = vk::createComputePipeline(ctx_, module_.get(), set_->pipelineLayout());
  localSize_ = module.interface.localSize[0];
}

SkyIrradianceBuilder::~SkyIrradianceBuilder() { vkDeviceWaitIdle(ctx_.device()); }

const SkyIrradiance& SkyIrradianceBuilder::irradianceFor(const FrameState& frame) {
  const SkyInputs inputs = skyInputs(frame);
  if (built_ == inputs) return irradiance_;
  const auto count = static_cast<std::uint32_t>(samples_.size());
  ctx_.submitAndWait([&](VkCommandBuffer cmd) {
    VkDescriptorSet set = set_->set();
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_.get());
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, set_->pipelineLayout(), 0, 1, &set, 0, nullptr);
    vkCmdPushConstants(cmd, set_->pipelineLayout(), VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof inputs, &inputs);
    vkCmdDispatch(cmd, (count + localSize_ - 1) / localSize_, 1, 1);
    vk::computeToHostBarrier(cmd);
  });
  const auto* texels = static_cast<const glm::vec4*>(radiance_.mapped());
  std::vector<glm::vec3> radiance(count);
  for (std::uint32_t i = 0; i < count; ++i) radiance[i] = glm::vec3(texels[i]);
  irradiance_ = projectSkyIrradiance(samples_, radiance);
  built_ = inputs;
  ++builds_;
  return irradiance_;
}

}  // namespace wg
