// Graphics pipelines for one compiled material, built from its reflection: descriptor
// set layouts (set 0 frame + shared maps, set 1 material), the vertex format and the
// pipelines the renderer needs (lit colour, blended for alphaMode blend; depth only for
// shadow and sky-exposure maps).
#pragma once
#include <vector>

#include "backends/spirv/spirv_toolchain.hpp"
#include "runtime/vulkan/material_reflection.hpp"
#include "runtime/vulkan/vulkan_context.hpp"

namespace wg::vk {

struct VertexLayout {
  std::uint32_t stride = 0;
  std::vector<VkVertexInputAttributeDescription> attributes;
  std::vector<std::string> names;  // per attribute, as reflected ("position", ...)
};

VertexLayout vertexLayoutFrom(const MaterialReflection& reflection);

class MaterialPipeline {
 public:
  MaterialPipeline(Context& ctx, const MaterialReflection& reflection, const SpirvWords& vertex,
                   const SpirvWords& fragment, VkRenderPass colourPass, VkRenderPass depthPass);
  ~MaterialPipeline();
  MaterialPipeline(const MaterialPipeline&) = delete;
  MaterialPipeline& operator=(const MaterialPipeline&) = delete;

  // The lit colour pipeline; for an AOV (a debug view) a blended material is drawn
  // opaque with depth writes, so read-backs see its attributes unblended.
  VkPipeline colourPipeline(bool aov = false) const { return aov && aov_ ? aov_ : colour_; }
  VkPipeline depthPipeline() const { return depth_; }
  VkPipelineLayout layout() const { return layout_; }
  VkDescriptorSetLayout setLayout(std::uint32_t set) const { return setLayouts_[set]; }
  const VertexLayout& vertexLayout() const { return vertex_; }
  const MaterialReflection& reflection() const { return reflection_; }

 private:
  enum class Kind { Colour, Aov, Depth };
  VkShaderModule module(const SpirvWords& words);
  VkPipeline build(VkRenderPass pass, Kind kind);

  Context& ctx_;
  MaterialReflection reflection_;
  VertexLayout vertex_;
  VkShaderModule vertexModule_ = VK_NULL_HANDLE, fragmentModule_ = VK_NULL_HANDLE;
  VkDescriptorSetLayout setLayouts_[2] = {VK_NULL_HANDLE, VK_NULL_HANDLE};
  VkPipelineLayout layout_ = VK_NULL_HANDLE;
  VkPipeline colour_ = VK_NULL_HANDLE, depth_ = VK_NULL_HANDLE;
  VkPipeline aov_ = VK_NULL_HANDLE;  // blended materials only
};

// Formats of the renderer's attachments.
inline constexpr VkFormat kColourFormat = VK_FORMAT_R32G32B32A32_SFLOAT;  // AOVs read back unclamped, exactly
inline constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;

}  // namespace wg::vk
