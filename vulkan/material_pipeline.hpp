// Graphics pipelines for one compiled material, built from its reflection: descriptor
// set layouts (set 0 frame + shared maps, set 1 material), the vertex format and the
// pipelines the renderer needs (lit colour, blended for alphaMode blend; depth only for
// shadow and sky-exposure maps).
#pragma once
#include <vector>

#include "backends/spirv/spirv_toolchain.hpp"
#include "vulkan/material_reflection.hpp"
#include "vulkan/vulkan_context.hpp"
#include "vulkan/vulkan_handle.hpp"

namespace wg::vk {

struct VertexLayout {
  std::uint32_t stride = 0;
  std::vector<VkVertexInputAttributeDescription> attributes;
  std::vector<std::string> names;  // per attribute, as reflected ("position", ...)
};

VertexLayout vertexLayoutFrom(const MaterialReflection& reflection);

// The render passes a material's pipelines are built for: the lit colour pass
// (`litSamples` per pixel), the single-sampled pass the AOVs are drawn in, and the
// depth-only pass.
struct PipelinePasses {
  VkRenderPass lit = VK_NULL_HANDLE;
  VkSampleCountFlagBits litSamples = VK_SAMPLE_COUNT_1_BIT;
  VkRenderPass aov = VK_NULL_HANDLE;
  VkRenderPass depth = VK_NULL_HANDLE;
  VkPipelineCreateFlags flags = 0;  // for every pipeline (GraphicsPipelineSettings::flags)
};

class MaterialPipeline {
 public:
  MaterialPipeline(Context& ctx, const MaterialReflection& reflection, const SpirvWords& vertex,
                   const SpirvWords& fragment, const PipelinePasses& passes);

  // The lit colour pipeline; for an AOV (a debug view) the AOV pass's, single-sampled,
  // where a blended material is drawn opaque with depth writes, so read-backs see its
  // attributes unblended.
  VkPipeline colourPipeline(bool aov = false) const { return aov && aov_ ? aov_.get() : colour_.get(); }
  VkPipeline depthPipeline() const { return depth_.get(); }
  VkPipelineLayout layout() const { return layout_.get(); }
  VkDescriptorSetLayout setLayout(std::uint32_t set) const { return setLayouts_[set].get(); }
  const VertexLayout& vertexLayout() const { return vertex_; }
  const MaterialReflection& reflection() const { return reflection_; }

 private:
  enum class Kind { Colour, Aov, Depth };
  UniquePipeline build(VkRenderPass pass, Kind kind, VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT);

  Context& ctx_;
  MaterialReflection reflection_;
  VertexLayout vertex_;
  // Destroyed pipelines first, shader modules last.
  UniqueShaderModule vertexModule_, fragmentModule_;
  UniqueDescriptorSetLayout setLayouts_[2];
  UniquePipelineLayout layout_;
  UniquePipeline colour_, depth_;
  UniquePipeline aov_;  // for the AOV pass: its target is full-float, single-sampled
  VkPipelineCreateFlags flags_ = 0;
};

// Formats of the renderer's attachments.
// Lit frames are half floats, as engines' colour targets are; AOVs are read back
// unclamped and exactly, so they stay full floats.
inline constexpr VkFormat kColourFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
inline constexpr VkFormat kAovFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
inline constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;

}  // namespace wg::vk
