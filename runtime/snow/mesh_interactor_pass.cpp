#include "runtime/snow/mesh_interactor_pass.hpp"

#include <stdexcept>

#include "runtime/snow/deformation_shaders.hpp"
#include "runtime/vulkan/graphics_pipeline.hpp"
#include "runtime/vulkan/runtime_shader.hpp"

namespace wg::snow {

namespace {
constexpr VkShaderStageFlags kStages = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;

vk::UniqueRenderPass createAttachmentlessPass(VkDevice device) {
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  VkRenderPassCreateInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
  info.subpassCount = 1;
  info.pSubpasses = &subpass;
  VkRenderPass pass;
  vk::check(vkCreateRenderPass(device, &info, nullptr, &pass), "vkCreateRenderPass");
  return vk::UniqueRenderPass(device, pass);
}

vk::UniqueFramebuffer createAttachmentlessFramebuffer(VkDevice device, VkRenderPass pass, std::uint32_t size) {
  VkFramebufferCreateInfo info{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
  info.renderPass = pass;
  info.width = size;
  info.height = size;
  info.layers = 1;
  VkFramebuffer framebuffer;
  vk::check(vkCreateFramebuffer(device, &info, nullptr, &framebuffer), "vkCreateFramebuffer");
  return vk::UniqueFramebuffer(device, framebuffer);
}
}  // namespace

MeshInteractorPass::MeshInteractorPass(vk::Context& ctx, std::uint32_t resolution, const vk::Buffer& heights)
    : ctx_(ctx), resolution_(resolution) {
  if (!ctx.fragmentStoresAndAtomics())
    throw std::runtime_error("mesh interactors need the device feature fragmentStoresAndAtomics");
  vk::CompiledModule vertex = vk::compileRuntimeShader(meshVertexShaderSource(), vk::RuntimeStage::Vertex, "snow mesh vertex");
  vk::CompiledModule fragment =
      vk::compileRuntimeShader(meshFragmentShaderSource(), vk::RuntimeStage::Fragment, "snow mesh fragment");
  set_ = std::make_unique<vk::ReflectedDescriptorSet>(ctx_, std::vector{vertex.interface, fragment.interface}, kStages);
  if (set_->pushConstantBytes() != sizeof(MeshWindowConstants))
    throw std::runtime_error("snow mesh shaders: push constants are " + std::to_string(set_->pushConstantBytes()) +
                             " bytes, MeshWindowConstants " + std::to_string(sizeof(MeshWindowConstants)));
  set_->bindBuffer("Heights", heights);
  vertex_ = vk::createShaderModule(ctx_, vertex.words);
  fragment_ = vk::createShaderModule(ctx_, fragment.words);
  pass_ = createAttachmentlessPass(ctx_.device());
  framebuffer_ = createAttachmentlessFramebuffer(ctx_.device(), pass_.get(), resolution_);
}

MeshInteractorPass::~MeshInteractorPass() = default;

VkPipeline MeshInteractorPass::pipelineFor(std::uint32_t stride) {
  auto found = pipelines_.find(stride);
  if (found != pipelines_.end()) return found->second.get();
  VkVertexInputBindingDescription binding{0, stride, VK_VERTEX_INPUT_RATE_VERTEX};
  VkVertexInputAttributeDescription position{0, 0, VK_FORMAT_R32G32B32_SFLOAT, 0};
  vk::GraphicsPipelineSettings s;
  s.vertex = vertex_.get();
  s.fragment = fragment_.get();
  s.vertexInput.vertexBindingDescriptionCount = 1;
  s.vertexInput.pVertexBindingDescriptions = &binding;
  s.vertexInput.vertexAttributeDescriptionCount = 1;
  s.vertexInput.pVertexAttributeDescriptions = &position;
  s.layout = set_->pipelineLayout();
  s.pass = pass_.get();
  return pipelines_.emplace(stride, vk::createGraphicsPipeline(ctx_.device(), s)).first->second.get();
}

void MeshInteractorPass::record(VkCommandBuffer cmd, const WindowConstants& window, const SnowLevel& level,
                                std::span<const MeshInteractor> meshes) {
  if (meshes.empty()) return;
  VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
  begin.renderPass = pass_.get();
  begin.framebuffer = framebuffer_.get();
  begin.renderArea.extent = {resolution_, resolution_};
  vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
  VkViewport viewport{0.f, 0.f, float(resolution_), float(resolution_), 0.f, 1.f};
  VkRect2D scissor{{0, 0}, {resolution_, resolution_}};
  vkCmdSetViewport(cmd, 0, 1, &viewport);
  vkCmdSetScissor(cmd, 0, 1, &scissor);
  VkDescriptorSet set = set_->set();
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, set_->pipelineLayout(), 0, 1, &set, 0, nullptr);
  MeshWindowConstants c{};
  for (int axis = 0; axis < 2; ++axis) {
    c.origin[axis] = window.origin[axis];
    c.originSlot[axis] = window.originSlot[axis];
  }
  c.resolution = window.resolution;
  c.texelSize = window.texelSize;
  c.surfaceHeight = level.surfaceHeight;
  c.snowDepth = level.depth;
  for (const MeshInteractor& m : meshes) {
    if (m.indexCount == 0) continue;
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelineFor(m.vertexStride));
    c.model = m.model;
    vkCmdPushConstants(cmd, set_->pipelineLayout(), kStages, 0, sizeof(c), &c);
    vkCmdBindVertexBuffers(cmd, 0, 1, &m.vertices, &m.vertexOffset);
    vkCmdBindIndexBuffer(cmd, m.indices, m.indexOffset, m.indexType);
    vkCmdDrawIndexed(cmd, m.indexCount, 1, 0, 0, 0);
  }
  vkCmdEndRenderPass(cmd);
}

}  // namespace wg::snow
