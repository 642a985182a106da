// GLSL of the runtime's own passes (deformable snow, snow puffs, bloom) compiled with
// the project's glslang wrapper, validated with spirv-val and reflected with
// SPIRV-Cross. Throws std::runtime_error naming the shader when any step fails.
#pragma once
#include <string_view>

#include "backends/spirv/spirv_toolchain.hpp"
#include "vulkan/vulkan_context.hpp"
#include "vulkan/vulkan_handle.hpp"

namespace wg::vk {

enum class RuntimeStage : std::uint8_t { Compute, Vertex, Fragment };

struct CompiledModule {
  SpirvWords words;
  ModuleInterface interface;
};

CompiledModule compileRuntimeShader(std::string_view glsl, RuntimeStage stage, std::string_view what);

// A compute pipeline over `module`'s "main".
UniquePipeline createComputePipeline(Context& ctx, VkShaderModule module, VkPipelineLayout layout);

}  // namespace wg::vk
