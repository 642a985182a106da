#include "vulkan/reflected_descriptor_set.hpp"

#include <algorithm>
#include <stdexcept>

namespace wg::vk {

namespace {
VkDescriptorType descriptorType(ModuleBinding::Kind kind) {
  switch (kind) {
    case ModuleBinding::Kind::StorageBuffer: return VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    case ModuleBinding::Kind::UniformBuffer: return VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
    case ModuleBinding::Kind::StorageImage: return VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
    case ModuleBinding::Kind::SampledImage: return VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE;
    case ModuleBinding::Kind::Sampler: return VK_DESCRIPTOR_TYPE_SAMPLER;
  }
  throw std::logic_error("unknown binding kind");
}
}  // namespace

ReflectedDescriptorSet::ReflectedDescriptorSet(Context& ctx, const std::vector<ModuleInterface>& modules,
                                               VkShaderStageFlags stages)
    : ctx_(ctx), stages_(stages) {
  std::map<std::uint32_t, const ModuleBinding*> bySlot;
  for (const auto& m : modules) {
    for (const auto& b : m.bindings) {
      if (b.set != 0) throw std::runtime_error("runtime shaders: " + b.name + " is not in set 0");
      auto [it, fresh] = bySlot.emplace(b.binding, &b);
      if (!fresh && (it->second->name != b.name || it->second->kind != b.kind))
        throw std::runtime_error("runtime shaders: binding " + std::to_string(b.binding) + " is both " + it->second->name +
                                 " and " + b.name);
      bindings_[b.name] = b;
    }
    pushConstantBytes_ = std::max(pushConstantBytes_, m.pushConstantBytes);
  }
  std::vector<VkDescriptorSetLayoutBinding> layoutBindings;
  std::map<VkDescriptorType, std::uint32_t> typeCounts;
  for (const auto& [slot, b] : bySlot) {
    layoutBindings.push_back({slot, descriptorType(b->kind), 1, stages, nullptr});
    ++typeCounts[descriptorType(b->kind)];
  }
  VkDevice d = ctx_.device();
  VkDescriptorSetLayoutCreateInfo setInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  setInfo.bindingCount = static_cast<std::uint32_t>(layoutBindings.size());
  setInfo.pBindings = layoutBindings.data();
  VkDescriptorSetLayout setLayout;
  check(vkCreateDescriptorSetLayout(d, &setInfo, nullptr, &setLayout), "vkCreateDescriptorSetLayout");
  setLayout_ = UniqueDescriptorSetLayout(d, setLayout);
  VkPushConstantRange range{stages, 0, pushConstantBytes_};
  VkPipelineLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  layoutInfo.setLayoutCount = 1;
  layoutInfo.pSetLayouts = &setLayout;
  layoutInfo.pushConstantRangeCount = pushConstantBytes_ > 0 ? 1 : 0;
  layoutInfo.pPushConstantRanges = &range;
  VkPipelineLayout layout;
  check(vkCreatePipelineLayout(d, &layoutInfo, nullptr, &layout), "vkCreatePipelineLayout");
  layout_ = UniquePipelineLayout(d, layout);
  std::vector<VkDescriptorPoolSize> sizes;
  for (auto [type, count] : typeCounts) sizes.push_back({type, count});
  VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  poolInfo.maxSets = 1;
  poolInfo.poolSizeCount = static_cast<std::uint32_t>(sizes.size());
  poolInfo.pPoolSizes = sizes.data();
  VkDescriptorPool pool;
  check(vkCreateDescriptorPool(d, &poolInfo, nullptr, &pool), "vkCreateDescriptorPool");
  pool_ = UniqueDescriptorPool(d, pool);
  VkDescriptorSetAllocateInfo alloc{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  alloc.descriptorPool = pool;
  alloc.descriptorSetCount = 1;
  alloc.pSetLayouts = &setLayout;
  check(vkAllocateDescriptorSets(d, &alloc, &set_), "vkAllocateDescriptorSets");
}

const ModuleBinding& ReflectedDescriptorSet::find(const std::string& name) const {
  auto it = bindings_.find(name);
  if (it == bindings_.end()) throw std::runtime_error("runtime shaders declare no resource " + name);
  return it->second;
}

void ReflectedDescriptorSet::write(const ModuleBinding& b, const VkDescriptorBufferInfo* buffer,
                                   const VkDescriptorImageInfo* image) {
  VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
  w.dstSet = set_;
  w.dstBinding = b.binding;
  w.descriptorCount = 1;
  w.descriptorType = descriptorType(b.kind);
  w.pBufferInfo = buffer;
  w.pImageInfo = image;
  vkUpdateDescriptorSets(ctx_.device(), 1, &w, 0, nullptr);
}

void ReflectedDescriptorSet::bindBuffer(const std::string& name, const Buffer& buffer) {
  const ModuleBinding& b = find(name);
  if (b.kind != ModuleBinding::Kind::StorageBuffer && b.kind != ModuleBinding::Kind::UniformBuffer)
    throw std::runtime_error(name + " is not a buffer");
  VkDescriptorBufferInfo info{buffer.handle(), 0, VK_WHOLE_SIZE};
  write(b, &info, nullptr);
}

void ReflectedDescriptorSet::bindImage(const std::string& name, VkImageView view, VkImageLayout layout) {
  const ModuleBinding& b = find(name);
  if (b.kind != ModuleBinding::Kind::StorageImage && b.kind != ModuleBinding::Kind::SampledImage)
    throw std::runtime_error(name + " is not an image");
  VkDescriptorImageInfo info{VK_NULL_HANDLE, view, layout};
  write(b, nullptr, &info);
}

void ReflectedDescriptorSet::bindSampler(const std::string& name, VkSampler sampler) {
  const ModuleBinding& b = find(name);
  if (b.kind != ModuleBinding::Kind::Sampler) throw std::runtime_error(name + " is not a sampler");
  VkDescriptorImageInfo info{sampler, VK_NULL_HANDLE, VK_IMAGE_LAYOUT_UNDEFINED};
  write(b, nullptr, &info);
}

UniqueShaderModule createShaderModule(Context& ctx, const SpirvWords& words) {
  VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  info.codeSize = words.size() * sizeof(std::uint32_t);
  info.pCode = words.data();
  VkShaderModule m;
  check(vkCreateShaderModule(ctx.device(), &info, nullptr, &m), "vkCreateShaderModule");
  return UniqueShaderModule(ctx.device(), m);
}

}  // namespace wg::vk
