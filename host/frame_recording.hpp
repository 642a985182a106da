// Recording a render pass of material draws into a command buffer.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "host/object_upload.hpp"
#include "vulkan/material_pipeline.hpp"

namespace wg {

// One object's indexed draw: its pipeline, sets 0 and 1, its frame slice and mesh.
struct ObjectDraw {
  const vk::MaterialPipeline* pipeline = nullptr;
  VkPipeline handle = VK_NULL_HANDLE;  // one of pipeline's (colour, AOV or depth)
  std::array<VkDescriptorSet, 2> sets{};
  std::uint32_t frameOffset = 0;
  const UploadedMesh* mesh = nullptr;
};

// The pass to begin, its framebuffer and one clear value per attachment.
struct PassTarget {
  VkRenderPass pass = VK_NULL_HANDLE;
  VkFramebuffer framebuffer = VK_NULL_HANDLE;
  std::uint32_t width = 0, height = 0;
  std::vector<VkClearValue> clears;
};

// Begins the pass over the whole target, draws in the given order and ends it.
void recordPass(VkCommandBuffer cmd, const PassTarget& target, const std::vector<ObjectDraw>& draws);

}  // namespace wg
