// Drawing over a finished colour pass (soft particles: the snow puffs, the
// precipitation near the viewer): a render pass that loads the colour and keeps it,
// without a depth attachment, while the scene's depth is sampleable, and pipelines
// that blend premultiplied alpha over it.
#pragma once
#include "host/scene_renderer.hpp"
#include "vulkan/vulkan_handle.hpp"

namespace wg {

class ColourOverlay {
 public:
  explicit ColourOverlay(VkDevice device);
  VkRenderPass pass() const { return pass_.get(); }
  // A pipeline for this pass with no vertex input, no depth and premultiplied alpha
  // over the colour: src + (1 - src.a) dst.
  vk::UniquePipeline pipeline(VkShaderModule vertex, VkShaderModule fragment, VkPipelineLayout layout) const;
  // Moves the depth to SHADER_READ_ONLY_OPTIMAL and begins the pass over the colour,
  // with the viewport and scissor covering it.
  void begin(const ColourPassTargets& targets);
  // Ends the pass and gives the depth back in DEPTH_STENCIL_ATTACHMENT_OPTIMAL.
  void end(const ColourPassTargets& targets);

 private:
  VkDevice device_;
  vk::UniqueRenderPass pass_;
  vk::UniqueFramebuffer framebuffer_;  // the last frame's; kept until the next begin()
};

}  // namespace wg
