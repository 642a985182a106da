// Uniform-block reflection with SPIRV-Cross, used to check that the compiled modules
// really have the offsets our reflection JSON publishes.
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

}  // namespace wg
