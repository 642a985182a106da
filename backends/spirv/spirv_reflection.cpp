// Reflection with SPIRV-Cross: uniform blocks, used to check that the compiled modules
// really have the offsets our reflection JSON publishes, and resource counts, used to
// check the MSL and GLSL ES translations.
#include <spirv_cross/spirv_cross.hpp>

#include "backends/spirv/spirv_toolchain.hpp"

namespace wg {

std::vector<ReflectedBlock> reflectUniformBlocks(const SpirvWords& words) {
  spirv_cross::Compiler compiler(words);
  std::vector<ReflectedBlock> blocks;
  for (const auto& ub : compiler.get_shader_resources().uniform_buffers) {
    ReflectedBlock block;
    block.set = compiler.get_decoration(ub.id, spv::DecorationDescriptorSet);
    block.binding = compiler.get_decoration(ub.id, spv::DecorationBinding);
    const auto& type = compiler.get_type(ub.base_type_id);
    for (std::uint32_t i = 0; i < type.member_types.size(); ++i)
      block.members.push_back({compiler.get_member_name(ub.base_type_id, i), compiler.type_struct_member_offset(type, i)});
    blocks.push_back(std::move(block));
  }
  return blocks;
}

ReflectedResources reflectResources(const SpirvWords& words) {
  spirv_cross::Compiler compiler(words);
  auto count = [](const spirv_cross::ShaderResources& r) {
    return ResourceCounts{r.uniform_buffers.size(), r.separate_images.size(), r.separate_samplers.size()};
  };
  ReflectedResources out;
  out.entryPoint = compiler.get_entry_points_and_stages().front().name;
  out.declared = count(compiler.get_shader_resources());
  out.used = count(compiler.get_shader_resources(compiler.get_active_interface_variables()));
  return out;
}

}  // namespace wg
