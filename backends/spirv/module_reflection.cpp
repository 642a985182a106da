// Reflection of the runtime's own modules with SPIRV-Cross: blocks and images by (set,
// binding) and name, the push-constant block's size, and a compute module's workgroup
// size, so dispatch sizes and descriptor layouts follow the shader.
#include <spirv_cross/spirv_cross.hpp>

#include "backends/spirv/spirv_toolchain.hpp"

namespace wg {

ModuleInterface reflectModule(const SpirvWords& words) {
  spirv_cross::Compiler compiler(words);
  auto resources = compiler.get_shader_resources();
  ModuleInterface out;
  auto add = [&](const spirv_cross::Resource& r, ModuleBinding::Kind kind) {
    out.bindings.push_back({compiler.get_name(r.base_type_id), compiler.get_decoration(r.id, spv::DecorationDescriptorSet),
                            compiler.get_decoration(r.id, spv::DecorationBinding), kind});
  };
  for (const auto& r : resources.storage_buffers) add(r, ModuleBinding::Kind::StorageBuffer);
  for (const auto& r : resources.uniform_buffers) add(r, ModuleBinding::Kind::UniformBuffer);
  // Images are named by their variable, blocks by their type.
  auto addImage = [&](const spirv_cross::Resource& r, ModuleBinding::Kind kind) {
    out.bindings.push_back({r.name, compiler.get_decoration(r.id, spv::DecorationDescriptorSet),
                            compiler.get_decoration(r.id, spv::DecorationBinding), kind});
  };
  for (const auto& r : resources.storage_images) addImage(r, ModuleBinding::Kind::StorageImage);
  for (const auto& r : resources.separate_images) addImage(r, ModuleBinding::Kind::SampledImage);
  for (const auto& r : resources.separate_samplers) addImage(r, ModuleBinding::Kind::Sampler);
  for (const auto& r : resources.push_constant_buffers)
    out.pushConstantBytes = static_cast<std::uint32_t>(compiler.get_declared_struct_size(compiler.get_type(r.base_type_id)));
  if (compiler.get_execution_model() == spv::ExecutionModelGLCompute)
    for (std::uint32_t axis = 0; axis < 3; ++axis)
      out.localSize[axis] = compiler.get_execution_mode_argument(spv::ExecutionModeLocalSize, axis);
  return out;
}

}  // namespace wg
