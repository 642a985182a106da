#include "host/render_passes.hpp"

#include <stdexcept>

#include "vulkan/material_pipeline.hpp"

namespace wg {

namespace {
VkAttachmentDescription clearedAttachment(VkFormat format, VkImageLayout finalLayout) {
  VkAttachmentDescription a{};
  a.format = format;
  a.samples = VK_SAMPLE_COUNT_1_BIT;
  a.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  a.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  a.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  a.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  a.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  a.finalLayout = finalLayout;
  return a;
}

vk::UniqueRenderPass createRenderPass(VkDevice device, const VkRenderPassCreateInfo& info) {
  VkRenderPass pass;
  vk::check(vkCreateRenderPass(device, &info, nullptr, &pass), "vkCreateRenderPass");
  return vk::UniqueRenderPass(device, pass);
}
}  // namespace

vk::UniqueRenderPass createColourPass(VkDevice device, VkFormat colourFormat) {
  VkAttachmentDescription attachments[] = {
      clearedAttachment(colourFormat, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL),
      clearedAttachment(vk::kDepthFormat, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL)};
  VkAttachmentReference colourRef{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  VkAttachmentReference depthRef{1, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = 1;
  subpass.pColorAttachments = &colourRef;
  subpass.pDepthStencilAttachment = &depthRef;
  VkRenderPassCreateInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
  info.attachmentCount = 2;
  info.pAttachments = attachments;
  info.subpassCount = 1;
  info.pSubpasses = &subpass;
  return createRenderPass(device, info);
}

VkSampleCountFlagBits colourPassSamples(const vk::Context& ctx, VkSampleCountFlagBits wanted) {
  if (wanted == VK_SAMPLE_COUNT_1_BIT || !ctx.depthStencilResolve()) return VK_SAMPLE_COUNT_1_BIT;
  const VkPhysicalDeviceLimits& limits = ctx.properties().limits;
  VkSampleCountFlags counts = limits.framebufferColorSampleCounts & limits.framebufferDepthSampleCounts;
  VkImageFormatProperties colour{}, depth{};
  if (vkGetPhysicalDeviceImageFormatProperties(ctx.physicalDevice(), vk::kColourFormat, VK_IMAGE_TYPE_2D,
                                               VK_IMAGE_TILING_OPTIMAL, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT, 0,
                                               &colour) != VK_SUCCESS ||
      vkGetPhysicalDeviceImageFormatProperties(ctx.physicalDevice(), vk::kDepthFormat, VK_IMAGE_TYPE_2D,
                                               VK_IMAGE_TILING_OPTIMAL, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT, 0,
                                               &depth) != VK_SUCCESS)
    return VK_SAMPLE_COUNT_1_BIT;
  counts &= colour.sampleCounts & depth.sampleCounts;
  for (auto count = static_cast<unsigned>(wanted); count > 1; count >>= 1)  // the most the device has, up to `wanted`
    if (counts & count) return static_cast<VkSampleCountFlagBits>(count);
  return VK_SAMPLE_COUNT_1_BIT;
}

vk::UniqueRenderPass createMultisampledColourPass(const vk::Context& ctx, VkSampleCountFlagBits samples) {
  auto attachment = [&](VkFormat format, VkSampleCountFlagBits count, bool cleared, VkImageLayout finalLayout) {
    VkAttachmentDescription2 a{VK_STRUCTURE_TYPE_ATTACHMENT_DESCRIPTION_2};
    a.format = format;
    a.samples = count;
    a.loadOp = cleared ? VK_ATTACHMENT_LOAD_OP_CLEAR : VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    a.storeOp = cleared ? VK_ATTACHMENT_STORE_OP_DONT_CARE : VK_ATTACHMENT_STORE_OP_STORE;
    a.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    a.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    a.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    a.finalLayout = finalLayout;
    return a;
  };
  const VkImageLayout colourLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  const VkImageLayout depthLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
  VkAttachmentDescription2 attachments[] = {
      attachment(vk::kColourFormat, samples, true, colourLayout), attachment(vk::kDepthFormat, samples, true, depthLayout),
      attachment(vk::kColourFormat, VK_SAMPLE_COUNT_1_BIT, false, colourLayout),
      attachment(vk::kDepthFormat, VK_SAMPLE_COUNT_1_BIT, false, depthLayout)};
  auto reference = [](std::uint32_t index, VkImageLayout layout, VkImageAspectFlags aspect) {
    VkAttachmentReference2 r{VK_STRUCTURE_TYPE_ATTACHMENT_REFERENCE_2};
    r.attachment = index;
    r.layout = layout;
    r.aspectMask = aspect;
    return r;
  };
  const VkAttachmentReference2 colourRef = reference(0, colourLayout, VK_IMAGE_ASPECT_COLOR_BIT);
  const VkAttachmentReference2 depthRef = reference(1, depthLayout, VK_IMAGE_ASPECT_DEPTH_BIT);
  const VkAttachmentReference2 colourResolve = reference(2, colourLayout, VK_IMAGE_ASPECT_COLOR_BIT);
  const VkAttachmentReference2 depthResolve = reference(3, depthLayout, VK_IMAGE_ASPECT_DEPTH_BIT);
  VkSubpassDescriptionDepthStencilResolve resolveDepth{VK_STRUCTURE_TYPE_SUBPASS_DESCRIPTION_DEPTH_STENCIL_RESOLVE};
  resolveDepth.depthResolveMode = VK_RESOLVE_MODE_SAMPLE_ZERO_BIT;  // every implementation has it
  resolveDepth.stencilResolveMode = VK_RESOLVE_MODE_NONE;
  resolveDepth.pDepthStencilResolveAttachment = &depthResolve;
  VkSubpassDescription2 subpass{VK_STRUCTURE_TYPE_SUBPASS_DESCRIPTION_2};
  subpass.pNext = &resolveDepth;
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = 1;
  subpass.pColorAttachments = &colourRef;
  subpass.pResolveAttachments = &colourResolve;
  subpass.pDepthStencilAttachment = &depthRef;
  VkRenderPassCreateInfo2 info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO_2};
  info.attachmentCount = 4;
  info.pAttachments = attachments;
  info.subpassCount = 1;
  info.pSubpasses = &subpass;
  auto create = reinterpret_cast<PFN_vkCreateRenderPass2KHR>(vkGetDeviceProcAddr(ctx.device(), "vkCreateRenderPass2KHR"));
  if (!create) throw std::runtime_error("vkCreateRenderPass2KHR is missing");
  VkRenderPass pass;
  vk::check(create(ctx.device(), &info, nullptr, &pass), "vkCreateRenderPass2KHR");
  return vk::UniqueRenderPass(ctx.device(), pass);
}

vk::UniqueRenderPass createDepthOnlyPass(VkDevice device) {
  VkAttachmentDescription depth = clearedAttachment(vk::kDepthFormat, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
  VkAttachmentReference depthRef{0, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
  // An unused colour slot: alpha-tested materials run their fragment stage here for its
  // discard, and its colour output goes nowhere.
  VkAttachmentReference unusedColour{VK_ATTACHMENT_UNUSED, VK_IMAGE_LAYOUT_UNDEFINED};
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = 1;
  subpass.pColorAttachments = &unusedColour;
  subpass.pDepthStencilAttachment = &depthRef;
  // The colour pass samples the map afterwards.
  VkSubpassDependency after{};
  after.srcSubpass = 0;
  after.dstSubpass = VK_SUBPASS_EXTERNAL;
  after.srcStageMask = VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
  after.dstStageMask = VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT;
  after.srcAccessMask = VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
  after.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_TRANSFER_READ_BIT;
  VkRenderPassCreateInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
  info.attachmentCount = 1;
  info.pAttachments = &depth;
  info.subpassCount = 1;
  info.pSubpasses = &subpass;
  info.dependencyCount = 1;
  info.pDependencies = &after;
  return createRenderPass(device, info);
}

vk::UniqueFramebuffer createFramebuffer(VkDevice device, VkRenderPass pass, const std::vector<VkImageView>& views,
                                        std::uint32_t width, std::uint32_t height) {
  VkFramebufferCreateInfo info{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
  info.renderPass = pass;
  info.attachmentCount = static_cast<std::uint32_t>(views.size());
  info.pAttachments = views.data();
  info.width = width;
  info.height = height;
  info.layers = 1;
  VkFramebuffer framebuffer;
  vk::check(vkCreateFramebuffer(device, &info, nullptr, &framebuffer), "vkCreateFramebuffer");
  return vk::UniqueFramebuffer(device, framebuffer);
}

}  // namespace wg
