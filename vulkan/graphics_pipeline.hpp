// A graphics pipeline from the few settings the runtime's pipelines differ in; the
// rest is fixed: triangle lists, fill, dynamic viewport and scissor.
#pragma once
#include <optional>

#include "vulkan/vulkan_context.hpp"
#include "vulkan/vulkan_handle.hpp"

namespace wg::vk {

struct GraphicsPipelineSettings {
  VkShaderModule vertex = VK_NULL_HANDLE;
  VkShaderModule fragment = VK_NULL_HANDLE;  // none: depth only
  VkPipelineVertexInputStateCreateInfo vertexInput{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
  VkCullModeFlags cullMode = VK_CULL_MODE_NONE;
  // Depth test (less or equal) and whether it writes; none for a pass without depth.
  std::optional<bool> depthWrite;
  // The colour attachment's blend state; none for a pass without colour.
  std::optional<VkPipelineColorBlendAttachmentState> colour;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VkRenderPass pass = VK_NULL_HANDLE;
  // Must match the pass's attachments (the lit colour pass may be multisampled).
  VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
  // VK_PIPELINE_CREATE_CAPTURE_STATISTICS_BIT_KHR where a tool reads the driver's statistics.
  VkPipelineCreateFlags flags = 0;
};

UniquePipeline createGraphicsPipeline(VkDevice device, const GraphicsPipelineSettings& settings);

// Writes to every channel, without blending.
VkPipelineColorBlendAttachmentState opaqueColour();

}  // namespace wg::vk
