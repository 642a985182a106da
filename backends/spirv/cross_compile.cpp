// SPIR-V -> GLSL ES and MSL with SPIRV-Cross, with resource slots ranked by
// (descriptor set, binding) so that output never depends on declaration order.
#include "backends/spirv/cross_compile.hpp"

#include <spirv_cross/spirv_glsl.hpp>
#include <spirv_cross/spirv_msl.hpp>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <tuple>
#include <vector>

namespace wg {

namespace {

// 3.10 is the first ES version with `layout(binding = N)` on blocks and samplers; without
// it an engine would have to look every slot up by name.
constexpr std::uint32_t kGlslEsVersion = 310;
// 2.0 is the oldest MSL 2 (macOS 10.13, iOS 11); nothing we emit needs a later one.
constexpr std::uint32_t kMslMajor = 2;
constexpr std::uint32_t kMslMinor = 0;

spv::ExecutionModel executionModel(ShaderStage stage) {
  return stage == ShaderStage::Vertex ? spv::ExecutionModelVertex : spv::ExecutionModelFragment;
}

struct SetBinding {
  std::uint32_t set, binding;
  auto operator<=>(const SetBinding&) const = default;
};

SetBinding setBindingOf(const spirv_cross::Compiler& compiler, spirv_cross::ID id) {
  return {compiler.get_decoration(id, spv::DecorationDescriptorSet),
          compiler.get_decoration(id, spv::DecorationBinding)};
}

// Our blocks are anonymous (`uniform FrameBlock { ... };`), which SPIRV-Cross would
// name after their SPIR-V ids; name the instance after the block instead: frameBlock.
void nameAnonymousBlocks(spirv_cross::Compiler& compiler,
                         const spirv_cross::SmallVector<spirv_cross::Resource>& blocks) {
  for (const auto& block : blocks) {
    if (!compiler.get_name(block.id).empty()) continue;
    std::string name = compiler.get_name(block.base_type_id);
    if (name.empty()) continue;
    name[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(name[0])));
    compiler.set_name(block.id, name);
  }
}

// A resource with its slot: its rank by (set, binding) among the resources of its kind.
struct Slotted {
  spirv_cross::ID id;
  std::uint32_t slot;
};

std::vector<Slotted> slotsBySetBinding(const spirv_cross::Compiler& compiler,
                                       const spirv_cross::SmallVector<spirv_cross::Resource>& resources) {
  std::vector<std::pair<SetBinding, spirv_cross::ID>> keyed;
  for (const auto& r : resources) keyed.push_back({setBindingOf(compiler, r.id), r.id});
  std::sort(keyed.begin(), keyed.end(),
            [](const auto& a, const auto& b) { return std::tie(a.first, a.second) < std::tie(b.first, b.second); });
  std::vector<Slotted> out;
  for (std::uint32_t i = 0; i < keyed.size(); ++i) out.push_back({keyed[i].second, i});
  return out;
}

// Combined samplers are named <texture>_<sampler> and take their texture's slot, so a
// sampler uniform has the same binding in both stages, as GL's program link requires.
// Empty, or why the module cannot be expressed that way.
std::string nameAndBindCombinedSamplers(spirv_cross::CompilerGLSL& compiler,
                                        const std::vector<Slotted>& imageSlots) {
  std::vector<bool> taken(imageSlots.size(), false);
  for (const auto& c : compiler.get_combined_image_samplers()) {
    std::string texture = compiler.get_name(c.image_id);
    auto image = std::find_if(imageSlots.begin(), imageSlots.end(), [&](const Slotted& s) { return s.id == c.image_id; });
    if (image == imageSlots.end()) return "texture " + texture + " is not a global resource";
    if (taken[image->slot]) return "texture " + texture + " is sampled with more than one sampler";
    taken[image->slot] = true;
    compiler.set_name(c.combined_id, texture + "_" + compiler.get_name(c.sampler_id));
    compiler.set_decoration(c.combined_id, spv::DecorationBinding, image->slot);
  }
  return "";
}

}  // namespace

CrossResult spirvToGlslEs(const SpirvWords& words, ShaderStage stage) {
  CrossResult result;
  try {
    spirv_cross::CompilerGLSL compiler(words);
    compiler.set_entry_point("main", executionModel(stage));
    auto options = compiler.get_common_options();
    options.es = true;
    options.version = kGlslEsVersion;
    options.vulkan_semantics = false;
    // World positions, noise and HDR lighting need full precision; ES fragment
    // shaders would otherwise default to mediump.
    options.fragment.default_float_precision = spirv_cross::CompilerGLSL::Options::Highp;
    options.fragment.default_int_precision = spirv_cross::CompilerGLSL::Options::Highp;
    compiler.set_common_options(options);

    auto resources = compiler.get_shader_resources();
    nameAnonymousBlocks(compiler, resources.uniform_buffers);
    // GL has no descriptor sets: give each uniform block its own binding point.
    for (const auto& [id, slot] : slotsBySetBinding(compiler, resources.uniform_buffers)) {
      compiler.unset_decoration(id, spv::DecorationDescriptorSet);
      compiler.set_decoration(id, spv::DecorationBinding, slot);
    }
    // GL ES has no separate texture and sampler objects.
    compiler.build_combined_image_samplers();
    result.error = nameAndBindCombinedSamplers(compiler, slotsBySetBinding(compiler, resources.separate_images));
    if (!result.error.empty()) return result;

    result.source = compiler.compile();
    result.entryPoint = compiler.get_cleansed_entry_point_name("main", executionModel(stage));
    result.ok = true;
  } catch (const spirv_cross::CompilerError& e) {
    result.error = e.what();
  }
  return result;
}

CrossResult spirvToMsl(const SpirvWords& words, ShaderStage stage) {
  CrossResult result;
  try {
    spirv_cross::CompilerMSL compiler(words);
    spv::ExecutionModel model = executionModel(stage);
    compiler.set_entry_point("main", model);
    auto options = compiler.get_msl_options();
    options.platform = spirv_cross::CompilerMSL::Options::macOS;
    options.set_msl_version(kMslMajor, kMslMinor);
    compiler.set_msl_options(options);

    // Metal has separate index spaces per kind: buffers, textures, samplers.
    auto resources = compiler.get_shader_resources();
    nameAnonymousBlocks(compiler, resources.uniform_buffers);
    using Binding = spirv_cross::MSLResourceBinding;
    auto bind = [&](const spirv_cross::SmallVector<spirv_cross::Resource>& list, std::uint32_t Binding::*index) {
      for (const auto& [id, slot] : slotsBySetBinding(compiler, list)) {
        Binding binding;
        binding.stage = model;
        binding.basetype = compiler.get_type(compiler.get_type_from_variable(id).self).basetype;
        SetBinding sb = setBindingOf(compiler, id);
        binding.desc_set = sb.set;
        binding.binding = sb.binding;
        binding.*index = slot;
        compiler.add_msl_resource_binding(binding);
      }
    };
    bind(resources.uniform_buffers, &Binding::msl_buffer);
    bind(resources.separate_images, &Binding::msl_texture);
    bind(resources.separate_samplers, &Binding::msl_sampler);

    result.source = compiler.compile();
    result.entryPoint = compiler.get_cleansed_entry_point_name("main", model);
    result.ok = true;
  } catch (const spirv_cross::CompilerError& e) {
    result.error = e.what();
  }
  return result;
}

}  // namespace wg
