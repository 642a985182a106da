// One descriptor set and pipeline layout for the runtime's own passes (deformable snow,
// snow puffs, bloom), built from the SPIRV-Cross reflection of their modules: the set
// is the union of what the modules declare (all in set 0), the push-constant range is
// the largest they declare. Resources are bound by name, never by slot number.
#pragma once
#include <map>
#include <string>
#include <vector>

#include "backends/spirv/spirv_toolchain.hpp"
#include "vulkan/gpu_buffer.hpp"
#include "vulkan/vulkan_handle.hpp"

namespace wg::vk {

class ReflectedDescriptorSet {
 public:
  ReflectedDescriptorSet(Context& ctx, const std::vector<ModuleInterface>& modules, VkShaderStageFlags stages);
  ReflectedDescriptorSet(const ReflectedDescriptorSet&) = delete;
  ReflectedDescriptorSet& operator=(const ReflectedDescriptorSet&) = delete;

  VkPipelineLayout pipelineLayout() const { return layout_.get(); }
  VkDescriptorSet set() const { return set_; }
  std::uint32_t pushConstantBytes() const { return pushConstantBytes_; }
  VkShaderStageFlags stages() const { return stages_; }

  // Throw std::runtime_error when no module declares `name` with that kind.
  void bindBuffer(const std::string& name, const Buffer& buffer);
  void bindImage(const std::string& name, VkImageView view, VkImageLayout layout);
  void bindSampler(const std::string& name, VkSampler sampler);

 private:
  const ModuleBinding& find(const std::string& name) const;
  void write(const ModuleBinding& b, const VkDescriptorBufferInfo* buffer, const VkDescriptorImageInfo* image);

  Context& ctx_;
  VkShaderStageFlags stages_;
  std::map<std::string, ModuleBinding> bindings_;
  UniqueDescriptorSetLayout setLayout_;
  UniquePipelineLayout layout_;
  UniqueDescriptorPool pool_;
  VkDescriptorSet set_ = VK_NULL_HANDLE;  // freed with pool_
  std::uint32_t pushConstantBytes_ = 0;
};

// A shader module from SPIR-V words.
UniqueShaderModule createShaderModule(Context& ctx, const SpirvWords& words);

}  // namespace wg::vk
