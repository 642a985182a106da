// Reflection of the runtime's compute modules with SPIRV-Cross: storage and uniform
// blocks by (set, binding) and block name, the push-constant block's size, and the
// workgroup size, so dispatch sizes and descriptor layouts follow the shader.
#include <spirv_cross/spirv_cross.hpp>

#include "backends/spirv/spirv_toolchain.hpp"

namespace wg {

ComputeInterface reflectCompute(const SpirvWords& words) {
  spirv_cross::Compiler compiler(words);
  auto resources = compiler.get_shader_resources();
  ComputeInterface out;
  auto add = [&](const spirv_cross::Resource& r, ComputeBinding::Kind kind) {
    out.bindings.push_back({compiler.get_name(r.base_type_id), compiler.get_decoration(r.id, spv::DecorationDescriptorSet),
                            compiler.get_decoration(r.id, spv::DecorationBinding), kind});
  };
  for (const auto& r : resources.storage_buffers) add(r, ComputeBinding::Kind::StorageBuffer);
  for (const auto& r : resources.uniform_buffers) add(r, ComputeBinding::Kind::UniformBuffer);
  for (const auto& r : resources.push_constant_buffers)
    out.pushConstantBytes = static_cast<std::uint32_t>(compiler.get_declared_struct_size(compiler.get_type(r.base_type_id)));
  for (std::uint32_t axis = 0; axis < 3; ++axis)
    out.localSize[axis] = compiler.get_execution_mode_argument(spv::ExecutionModeLocalSize, axis);
  return out;
}

}  // namespace wg
