#include "vulkan/runtime_shader.hpp"

#include <stdexcept>
#include <string>

namespace wg::vk {

CompiledModule compileRuntimeShader(std::string_view glsl, RuntimeStage stage, std::string_view what) {
  SpirvCompileResult r = stage == RuntimeStage::Compute ? compileComputeToSpirv(glsl)
                         : compileToSpirv(glsl, ShaderLanguage::Glsl,
                                          stage == RuntimeStage::Vertex ? ShaderStage::Vertex : ShaderStage::Fragment);
  if (!r.ok) throw std::runtime_error(std::string(what) + " shader: " + r.log);
  if (std::string problem = validateSpirv(r.words); !problem.empty())
    throw std::runtime_error(std::string(what) + " shader: " + problem);
  ModuleInterface interface = reflectModule(r.words);
  return {std::move(r.words), std::move(interface)};
}

UniquePipeline createComputePipeline(Context& ctx, VkShaderModule module, VkPipelineLayout layout) {
  VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
  info.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
  info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
  info.stage.module = module;
  info.stage.pName = "main";
  info.layout = layout;
  VkPipeline pipeline;
  check(vkCreateComputePipelines(ctx.device(), VK_NULL_HANDLE, 1, &info, nullptr, &pipeline), "vkCreateComputePipelines");
  return UniquePipeline(ctx.device(), pipeline);
}

}  // namespace wg::vk
