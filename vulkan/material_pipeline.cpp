#include "vulkan/material_pipeline.hpp"

#include <algorithm>
#include <stdexcept>

#include "vulkan/graphics_pipeline.hpp"
#include "vulkan/reflected_descriptor_set.hpp"

namespace wg::vk {

namespace {
VkFormat vertexFormat(std::string_view type) {
  if (type == "float") return VK_FORMAT_R32_SFLOAT;
  if (type == "vec2") return VK_FORMAT_R32G32_SFLOAT;
  if (type == "vec3") return VK_FORMAT_R32G32B32_SFLOAT;
  if (type == "vec4") return VK_FORMAT_R32G32B32A32_SFLOAT;
  throw std::runtime_error("reflection: vertex input type '" + std::string(type) + "' has no vertex format");
}

// Straight (not premultiplied) alpha, "over": colour = src * a + dst * (1 - a), and
// the stored alpha accumulates coverage the same way.
VkPipelineColorBlendAttachmentState straightAlphaBlend() {
  VkPipelineColorBlendAttachmentState b = opaqueColour();
  b.blendEnable = VK_TRUE;
  b.srcColorBlendFactor = VK_BLEND_FACTOR_SRC_ALPHA;
  b.dstColorBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
  b.colorBlendOp = VK_BLEND_OP_ADD;
  b.srcAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
  b.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
  b.alphaBlendOp = VK_BLEND_OP_ADD;
  return b;
}

constexpr VkShaderStageFlags kAllStages = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;

void addTextureBindings(std::vector<VkDescriptorSetLayoutBinding>& bindings, const std::vector<ReflectedTexture>& list) {
  for (const auto& t : list) {
    bindings.push_back({t.binding, VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE, 1, kAllStages, nullptr});
    bindings.push_back({t.samplerBinding, VK_DESCRIPTOR_TYPE_SAMPLER, 1, kAllStages, nullptr});
  }
}
}  // namespace

VertexLayout vertexLayoutFrom(const MaterialReflection& r) {
  VertexLayout layout;
  auto inputs = r.vertexInputs;
  std::sort(inputs.begin(), inputs.end(), [](const auto& a, const auto& b) { return a.location < b.location; });
  for (const auto& input : inputs) {
    layout.attributes.push_back({input.location, 0, vertexFormat(input.type), layout.stride});
    layout.names.push_back(input.name);
    layout.stride += reflectedTypeSize(input.type);
  }
  return layout;
}

MaterialPipeline::MaterialPipeline(Context& ctx, const MaterialReflection& reflection, const SpirvWords& vertex,
                                   const SpirvWords& fragment, const PipelinePasses& passes)
    : ctx_(ctx), reflection_(reflection), vertex_(vertexLayoutFrom(reflection)) {
  vertexModule_ = createShaderModule(ctx, vertex);
  fragmentModule_ = createShaderModule(ctx, fragment);

  // Set 0: the frame block (dynamic: one slice per object) and the shared maps.
  std::vector<VkDescriptorSetLayoutBinding> set0 = {
      {reflection.frame.binding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, 1, kAllStages, nullptr}};
  addTextureBindings(set0, reflection.weatherMaps);
  // Set 1: the material block, when it has members, and the material's textures.
  std::vector<VkDescriptorSetLayoutBinding> set1;
  if (!reflection.material.members.empty())
    set1.push_back({reflection.material.binding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, kAllStages, nullptr});
  addTextureBindings(set1, reflection.textures);
  VkDescriptorSetLayout layouts[2];
  for (int s = 0; s < 2; ++s) {
    const auto& bindings = s == 0 ? set0 : set1;
    VkDescriptorSetLayoutCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    info.bindingCount = static_cast<std::uint32_t>(bindings.size());
    info.pBindings = bindings.data();
    check(vkCreateDescriptorSetLayout(ctx.device(), &info, nullptr, &layouts[s]), "vkCreateDescriptorSetLayout");
    setLayouts_[s] = UniqueDescriptorSetLayout(ctx.device(), layouts[s]);
  }
  VkPipelineLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  layoutInfo.setLayoutCount = 2;
  layoutInfo.pSetLayouts = layouts;
  VkPipelineLayout layout;
  check(vkCreatePipelineLayout(ctx.device(), &layoutInfo, nullptr, &layout), "vkCreatePipelineLayout");
  layout_ = UniquePipelineLayout(ctx.device(), layout);
  flags_ = passes.flags;
  colour_ = build(passes.lit, Kind::Colour, passes.litSamples);
  if (passes.aov != VK_NULL_HANDLE) aov_ = build(passes.aov, Kind::Aov);
  depth_ = build(passes.depth, Kind::Depth);
}

UniquePipeline MaterialPipeline::build(VkRenderPass pass, Kind kind, VkSampleCountFlagBits samples) {
  const bool depthOnly = kind == Kind::Depth;
  const bool blended = kind == Kind::Colour && reflection_.blended();
  VkVertexInputBindingDescription binding{0, vertex_.stride, VK_VERTEX_INPUT_RATE_VERTEX};
  GraphicsPipelineSettings settings;
  settings.vertex = vertexModule_.get();
  // Depth maps run the material's own vertex stage (snow displacement casts shadows).
  // Alpha-tested materials run their fragment stage there too, for its discard: a
  // foliage card that snow has thinned away casts no shadow. Others need none.
  if (!depthOnly || reflection_.alphaTested) settings.fragment = fragmentModule_.get();
  settings.vertexInput.vertexBindingDescriptionCount = 1;
  settings.vertexInput.pVertexBindingDescriptions = &binding;
  settings.vertexInput.vertexAttributeDescriptionCount = static_cast<std::uint32_t>(vertex_.attributes.size());
  settings.vertexInput.pVertexAttributeDescriptions = vertex_.attributes.data();
  // Alpha-tested cards and double-sided materials show both faces; depth maps see every
  // face (thin roofs included).
  const bool twoSided = depthOnly || reflection_.alphaTested || reflection_.doubleSided;
  settings.cullMode = twoSided ? VK_CULL_MODE_NONE : VK_CULL_MODE_BACK_BIT;
  settings.depthWrite = !blended;  // blended surfaces hide nothing
  settings.colour = depthOnly ? VkPipelineColorBlendAttachmentState{} : blended ? straightAlphaBlend() : opaqueColour();
  settings.layout = layout_.get();
  settings.pass = pass;
  settings.samples = samples;
  settings.flags = flags_;
  return createGraphicsPipeline(ctx_.device(), settings);
}

}  // namespace wg::vk
