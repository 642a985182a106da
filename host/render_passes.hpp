// The scene renderer's render passes and their framebuffers.
#pragma once
#include <cstdint>
#include <vector>

#include "vulkan/vulkan_context.hpp"
#include "vulkan/vulkan_handle.hpp"

namespace wg {

// RGBA32F colour kept for read-back and D32 depth kept for later passes (soft
// particles); both are left attachment-optimal.
vk::UniqueRenderPass createColourPass(VkDevice device, VkFormat colourFormat);
// The lit colour pass's samples per pixel on this device: 4 where the colour and depth
// formats take 4 samples as attachments and the depth can be resolved
// (Context::depthStencilResolve); 1 otherwise.
VkSampleCountFlagBits colourPassSamples(const vk::Context& ctx, VkSampleCountFlagBits wanted);
// The colour pass drawn with `samples` samples per pixel: multisampled colour and depth
// (attachments 0 and 1, cleared, not stored) resolved at its end into single-sample
// colour (attachment 2: the average of the samples) and depth (attachment 3: sample 0),
// left in the layouts createColourPass leaves its own. Needs Context::depthStencilResolve.
vk::UniqueRenderPass createMultisampledColourPass(const vk::Context& ctx, VkSampleCountFlagBits samples);
// Depth only (shadow and sky-exposure maps): stored and left shader-readable.
vk::UniqueRenderPass createDepthOnlyPass(VkDevice device);
vk::UniqueFramebuffer createFramebuffer(VkDevice device, VkRenderPass pass, const std::vector<VkImageView>& views,
                                        std::uint32_t width, std::uint32_t height);

}  // namespace wg
