// The scene renderer's render passes and their framebuffers.
#pragma once
#include <cstdint>
#include <vector>

#include "runtime/vulkan/vulkan_handle.hpp"

namespace wg {

// RGBA32F colour kept for read-back and D32 depth kept for later passes (soft
// particles); both are left attachment-optimal.
vk::UniqueRenderPass createColourPass(VkDevice device);
// Depth only (shadow and sky-exposure maps): stored and left shader-readable.
vk::UniqueRenderPass createDepthOnlyPass(VkDevice device);
vk::UniqueFramebuffer createFramebuffer(VkDevice device, VkRenderPass pass, const std::vector<VkImageView>& views,
                                        std::uint32_t width, std::uint32_t height);

}  // namespace wg
