#include "runtime/vulkan/material_pipeline.hpp"

#include <algorithm>
#include <stdexcept>

#include "runtime/vulkan/reflected_descriptor_set.hpp"

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
  VkPipelineColorBlendAttachmentState b{};
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
                                   const SpirvWords& fragment, VkRenderPass colourPass, VkRenderPass depthPass)
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
  colour_ = build(colourPass, Kind::Colour);
  if (reflection.blended()) aov_ = build(colourPass, Kind::Aov);
  depth_ = build(depthPass, Kind::Depth);
}

UniquePipeline MaterialPipeline::build(VkRenderPass pass, Kind kind) {
  const bool depthOnly = kind == Kind::Depth;
  const bool blended = kind == Kind::Colour && reflection_.blended();
  VkPipelineShaderStageCreateInfo stages[2] = {{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO},
                                               {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO}};
  stages[0].stage = VK_SHADER_STAGE_VERTEX_BIT;
  stages[0].module = vertexModule_.get();
  stages[0].pName = "main";
  stages[1].stage = VK_SHADER_STAGE_FRAGMENT_BIT;
  stages[1].module = fragmentModule_.get();
  stages[1].pName = "main";

  VkVertexInputBindingDescription binding{0, vertex_.stride, VK_VERTEX_INPUT_RATE_VERTEX};
  VkPipelineVertexInputStateCreateInfo vertexInput{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
  vertexInput.vertexBindingDescriptionCount = 1;
  vertexInput.pVertexBindingDescriptions = &binding;
  vertexInput.vertexAttributeDescriptionCount = static_cast<std::uint32_t>(vertex_.attributes.size());
  vertexInput.pVertexAttributeDescriptions = vertex_.attributes.data();
  VkPipelineInputAssemblyStateCreateInfo assembly{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
  assembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  VkPipelineViewportStateCreateInfo viewport{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
  viewport.viewportCount = 1;
  viewport.scissorCount = 1;
  VkPipelineRasterizationStateCreateInfo raster{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
  raster.polygonMode = VK_POLYGON_MODE_FILL;
  // Alpha-tested cards and double-sided materials show both faces; depth maps see every
  // face (thin roofs included).
  const bool twoSided = depthOnly || reflection_.alphaTested || reflection_.doubleSided;
  raster.cullMode = twoSided ? VK_CULL_MODE_NONE : VK_CULL_MODE_BACK_BIT;
  raster.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
  raster.lineWidth = 1.f;
  VkPipelineMultisampleStateCreateInfo multisample{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
  multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
  VkPipelineDepthStencilStateCreateInfo depth{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
  depth.depthTestEnable = VK_TRUE;
  depth.depthWriteEnable = blended ? VK_FALSE : VK_TRUE;  // blended surfaces hide nothing
  depth.depthCompareOp = VK_COMPARE_OP_LESS_OR_EQUAL;
  VkPipelineColorBlendAttachmentState blendAttachment = blended ? straightAlphaBlend() : VkPipelineColorBlendAttachmentState{};
  blendAttachment.colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT | VK_COLOR_COMPONENT_B_BIT |
                                   VK_COLOR_COMPONENT_A_BIT;
  VkPipelineColorBlendStateCreateInfo blend{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
  blend.attachmentCount = depthOnly ? 0 : 1;
  blend.pAttachments = &blendAttachment;
  VkDynamicState dynamicStates[] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
  VkPipelineDynamicStateCreateInfo dynamic{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
  dynamic.dynamicStateCount = 2;
  dynamic.pDynamicStates = dynamicStates;

  VkGraphicsPipelineCreateInfo info{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
  // Depth maps run the material's own vertex stage (snow displacement casts shadows)
  // and no fragment stage.
  info.stageCount = depthOnly ? 1 : 2;
  info.pStages = stages;
  info.pVertexInputState = &vertexInput;
  info.pInputAssemblyState = &assembly;
  info.pViewportState = &viewport;
  info.pRasterizationState = &raster;
  info.pMultisampleState = &multisample;
  info.pDepthStencilState = &depth;
  info.pColorBlendState = &blend;
  info.pDynamicState = &dynamic;
  info.layout = layout_.get();
  info.renderPass = pass;
  VkPipeline pipeline;
  check(vkCreateGraphicsPipelines(ctx_.device(), VK_NULL_HANDLE, 1, &info, nullptr, &pipeline), "vkCreateGraphicsPipelines");
  return UniquePipeline(ctx_.device(), pipeline);
}

}  // namespace wg::vk
