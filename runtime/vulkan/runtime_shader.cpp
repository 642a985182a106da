#include "runtime/vulkan/runtime_shader.hpp"

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

}  // namespace wg::vk
