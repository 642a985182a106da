#include "snow/mesh_interactor_pass.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "snow/deformation_shaders.hpp"
#include "vulkan/graphics_pipeline.hpp"
#include "vulkan/runtime_shader.hpp"

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
  // Each mesh is scissored to its footprint, the pass to their union: the rasteriser
  // only visits the texels the meshes can reach.
  std::vector<VkRect2D> scissors;
  glm::ivec2 lo{int(resolution_)}, hi{0};
  for (const MeshInteractor& m : meshes) {
    glm::ivec2 a = glm::ivec2(glm::floor(m.footprintMin / window.texelSize)) - glm::ivec2(window.origin[0], window.origin[1]);
    glm::ivec2 b = glm::ivec2(glm::floor(m.footprintMax / window.texelSize)) - glm::ivec2(window.origin[0], window.origin[1]) + 1;
    a = glm::clamp(a, glm::ivec2(0), glm::ivec2(int(resolution_)));
    b = glm::clamp(b, glm::ivec2(0), glm::ivec2(int(resolution_)));
    scissors.push_back({{a.x, a.y}, {std::uint32_t(std::max(b.x - a.x, 0)), std::uint32_t(std::max(b.y - a.y, 0))}});
    if (m.indexCount != 0 && b.x > a.x && b.y > a.y) lo = glm::min(lo, a), hi = glm::max(hi, b);
  }
  if (hi.x <= lo.x || hi.y <= lo.y) return;  // every mesh outside the window
  VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
  begin.renderPass = pass_.get();
  begin.framebuffer = framebuffer_.get();
  begin.renderArea = {{lo.x, lo.y}, {std::uint32_t(hi.x - lo.x), std::uint32_t(hi.y - lo.y)}};
  vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
  VkViewport viewport{0.f, 0.f, float(resolution_), float(resolution_), 0.f, 1.f};
  vkCmdSetViewport(cmd, 0, 1, &viewport);
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
  for (std::size_t i = 0; i < meshes.size(); ++i) {
    const MeshInteractor& m = meshes[i];
    if (m.indexCount == 0 || scissors[i].extent.width == 0 || scissors[i].extent.height == 0) continue;
    vkCmdSetScissor(cmd, 0, 1, &scissors[i]);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelineFor(m.vertexStride));
    c.model = m.model;
    c.surfaceHeight = std::isfinite(m.surfaceHeight) ? m.surfaceHeight : level.surfaceHeight;
    vkCmdPushConstants(cmd, set_->pipelineLayout(), kStages, 0, sizeof(c), &c);
    vkCmdBindVertexBuffers(cmd, 0, 1, &m.vertices, &m.vertexOffset);
    vkCmdBindIndexBuffer(cmd, m.indices, m.indexOffset, m.indexType);
    vkCmdDrawIndexed(cmd, m.indexCount, 1, 0, 0, 0);
  }
  vkCmdEndRenderPass(cmd);
}

}  // namespace wg::snow
