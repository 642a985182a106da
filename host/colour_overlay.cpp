#include "host/colour_overlay.hpp"

#include "host/render_passes.hpp"
#include "vulkan/graphics_pipeline.hpp"

namespace wg {

namespace {
vk::UniqueRenderPass createOverlayPass(VkDevice d) {
  VkAttachmentDescription colour{};
  colour.format = vk::kColourFormat;
  colour.samples = VK_SAMPLE_COUNT_1_BIT;
  colour.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
  colour.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  colour.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  colour.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  colour.initialLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  colour.finalLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  VkAttachmentReference ref{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = 1;
  subpass.pColorAttachments = &ref;
  VkSubpassDependency before{};
  before.srcSubpass = VK_SUBPASS_EXTERNAL;
  before.dstSubpass = 0;
  before.srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  before.dstStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  before.srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  before.dstAccessMask = VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  VkRenderPassCreateInfo passInfo{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
  passInfo.attachmentCount = 1;
  passInfo.pAttachments = &colour;
  passInfo.subpassCount = 1;
  passInfo.pSubpasses = &subpass;
  passInfo.dependencyCount = 1;
  passInfo.pDependencies = &before;
  VkRenderPass pass;
  vk::check(vkCreateRenderPass(d, &passInfo, nullptr, &pass), "vkCreateRenderPass");
  return vk::UniqueRenderPass(d, pass);
}
}  // namespace

vk::UniquePipeline ColourOverlay::pipeline(VkShaderModule vertex, VkShaderModule fragment, VkPipelineLayout layout) const {
  VkPipelineColorBlendAttachmentState blend = vk::opaqueColour();
  blend.blendEnable = VK_TRUE;
  blend.srcColorBlendFactor = VK_BLEND_FACTOR_ONE;
  blend.dstColorBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
  blend.colorBlendOp = VK_BLEND_OP_ADD;
  blend.srcAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
  blend.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
  blend.alphaBlendOp = VK_BLEND_OP_ADD;
  vk::GraphicsPipelineSettings settings;
  settings.vertex = vertex;
  settings.fragment = fragment;
  settings.colour = blend;
  settings.layout = layout;
  settings.pass = pass_.get();
  return vk::createGraphicsPipeline(device_, settings);
}

ColourOverlay::ColourOverlay(VkDevice device) : device_(device), pass_(createOverlayPass(device)) {}

void ColourOverlay::begin(const ColourPassTargets& t) {
  // The previous frame has been submitted and waited for: its framebuffer can go.
  framebuffer_.reset();
  const std::uint32_t width = t.colour->width(), height = t.colour->height();
  framebuffer_ = createFramebuffer(device_, pass_.get(), {t.colour->view()}, width, height);
  vk::Image2D::transition(t.cmd, t.depth->handle(), VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
                          VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
  VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
  begin.renderPass = pass_.get();
  begin.framebuffer = framebuffer_.get();
  begin.renderArea = {{0, 0}, {width, height}};
  vkCmdBeginRenderPass(t.cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
  VkViewport viewport{0.f, 0.f, float(width), float(height), 0.f, 1.f};
  VkRect2D scissor{{0, 0}, {width, height}};
  vkCmdSetViewport(t.cmd, 0, 1, &viewport);
  vkCmdSetScissor(t.cmd, 0, 1, &scissor);
}

void ColourOverlay::end(const ColourPassTargets& t) {
  vkCmdEndRenderPass(t.cmd);
  vk::Image2D::transition(t.cmd, t.depth->handle(), VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                          VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL);
}

}  // namespace wg
