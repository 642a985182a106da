#include "runtime/snow/deformation_pass.hpp"

#include <stdexcept>

#include "backends/spirv/spirv_toolchain.hpp"
#include "runtime/snow/deformation_shaders.hpp"

namespace wg::snow {

namespace {
// All five blocks of the three modules, in one set.
constexpr std::uint32_t kMaxBindings = 8;

VkDescriptorType descriptorType(ComputeBinding::Kind kind) {
  return kind == ComputeBinding::Kind::StorageBuffer ? VK_DESCRIPTOR_TYPE_STORAGE_BUFFER : VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
}

std::uint32_t groups(int extent, std::uint32_t local) {
  return extent <= 0 ? 0u : (static_cast<std::uint32_t>(extent) + local - 1) / local;
}
}  // namespace

DeformationPass::DeformationPass(vk::Context& ctx) : ctx_(ctx) {
  // Compile and reflect first: the layout is the union of what the modules declare.
  struct Compiled {
    SpirvWords words;
    ComputeInterface interface;
  };
  std::vector<Compiled> modules;
  for (auto [source, what] : {std::pair{stampShaderSource(), "stamp"}, std::pair{normalShaderSource(), "normal"},
                              std::pair{refillShaderSource(), "refill"}}) {
    SpirvCompileResult r = compileComputeToSpirv(source);
    if (!r.ok) throw std::runtime_error(std::string("snow ") + what + " shader: " + r.log);
    if (std::string problem = validateSpirv(r.words); !problem.empty())
      throw std::runtime_error(std::string("snow ") + what + " shader: " + problem);
    modules.push_back({r.words, reflectCompute(r.words)});
  }
  std::map<std::uint32_t, ComputeBinding> bindings;
  for (const auto& m : modules) {
    for (const auto& b : m.interface.bindings) {
      if (b.set != 0) throw std::runtime_error("snow shaders: block " + b.name + " is not in set 0");
      auto [it, fresh] = bindings.emplace(b.binding, b);
      if (!fresh && (it->second.name != b.name || it->second.kind != b.kind))
        throw std::runtime_error("snow shaders: binding " + std::to_string(b.binding) + " is both " + it->second.name +
                                 " and " + b.name);
    }
    pushConstantBytes_ = std::max(pushConstantBytes_, m.interface.pushConstantBytes);
  }
  if (pushConstantBytes_ != sizeof(WindowConstants))
    throw std::runtime_error("snow shaders: push constants are " + std::to_string(pushConstantBytes_) +
                             " bytes, WindowConstants " + std::to_string(sizeof(WindowConstants)));
  std::vector<VkDescriptorSetLayoutBinding> layoutBindings;
  std::map<VkDescriptorType, std::uint32_t> typeCounts;
  for (const auto& [binding, b] : bindings) {
    layoutBindings.push_back({binding, descriptorType(b.kind), 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr});
    bindingOf_[b.name] = binding;
    ++typeCounts[descriptorType(b.kind)];
  }
  if (layoutBindings.size() > kMaxBindings) throw std::runtime_error("snow shaders: too many blocks");
  VkDevice d = ctx_.device();
  VkDescriptorSetLayoutCreateInfo setInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  setInfo.bindingCount = static_cast<std::uint32_t>(layoutBindings.size());
  setInfo.pBindings = layoutBindings.data();
  vk::check(vkCreateDescriptorSetLayout(d, &setInfo, nullptr, &setLayout_), "vkCreateDescriptorSetLayout");
  VkPushConstantRange range{VK_SHADER_STAGE_COMPUTE_BIT, 0, pushConstantBytes_};
  VkPipelineLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  layoutInfo.setLayoutCount = 1;
  layoutInfo.pSetLayouts = &setLayout_;
  layoutInfo.pushConstantRangeCount = 1;
  layoutInfo.pPushConstantRanges = &range;
  vk::check(vkCreatePipelineLayout(d, &layoutInfo, nullptr, &layout_), "vkCreatePipelineLayout");

  std::vector<VkDescriptorPoolSize> sizes;
  for (auto [type, count] : typeCounts) sizes.push_back({type, count});
  VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  poolInfo.maxSets = 1;
  poolInfo.poolSizeCount = static_cast<std::uint32_t>(sizes.size());
  poolInfo.pPoolSizes = sizes.data();
  vk::check(vkCreateDescriptorPool(d, &poolInfo, nullptr, &pool_), "vkCreateDescriptorPool");
  VkDescriptorSetAllocateInfo alloc{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  alloc.descriptorPool = pool_;
  alloc.descriptorSetCount = 1;
  alloc.pSetLayouts = &setLayout_;
  vk::check(vkAllocateDescriptorSets(d, &alloc, &set_), "vkAllocateDescriptorSets");

  Pipeline* targets[] = {&stamp_, &normals_, &refill_};
  for (std::size_t i = 0; i < modules.size(); ++i) {
    Pipeline& p = *targets[i];
    VkShaderModuleCreateInfo moduleInfo{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    moduleInfo.codeSize = modules[i].words.size() * sizeof(std::uint32_t);
    moduleInfo.pCode = modules[i].words.data();
    vk::check(vkCreateShaderModule(d, &moduleInfo, nullptr, &p.module), "vkCreateShaderModule");
    VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    info.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    info.stage.module = p.module;
    info.stage.pName = "main";
    info.layout = layout_;
    vk::check(vkCreateComputePipelines(d, VK_NULL_HANDLE, 1, &info, nullptr, &p.pipeline), "vkCreateComputePipelines");
    for (int axis = 0; axis < 3; ++axis) p.localSize[axis] = modules[i].interface.localSize[axis];
  }
}

DeformationPass::~DeformationPass() {
  VkDevice d = ctx_.device();
  vkDeviceWaitIdle(d);
  for (Pipeline* p : {&stamp_, &normals_, &refill_}) {
    vkDestroyPipeline(d, p->pipeline, nullptr);
    vkDestroyShaderModule(d, p->module, nullptr);
  }
  vkDestroyDescriptorPool(d, pool_, nullptr);
  vkDestroyPipelineLayout(d, layout_, nullptr);
  vkDestroyDescriptorSetLayout(d, setLayout_, nullptr);
}

void DeformationPass::bind(const std::string& block, const vk::Buffer& buffer) {
  auto it = bindingOf_.find(block);
  if (it == bindingOf_.end()) throw std::runtime_error("snow shaders declare no block " + block);
  VkDescriptorBufferInfo info{buffer.handle(), 0, VK_WHOLE_SIZE};
  VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
  write.dstSet = set_;
  write.dstBinding = it->second;
  write.descriptorCount = 1;
  write.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
  write.pBufferInfo = &info;
  vkUpdateDescriptorSets(ctx_.device(), 1, &write, 0, nullptr);
}

void DeformationPass::dispatch(VkCommandBuffer cmd, const Pipeline& p, const WindowConstants& window,
                               glm::ivec2 extent, std::uint32_t layers) const {
  std::uint32_t gx = groups(extent.x, p.localSize[0]), gy = groups(extent.y, p.localSize[1]);
  if (gx == 0 || gy == 0 || layers == 0) return;
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, p.pipeline);
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_, 0, 1, &set_, 0, nullptr);
  vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, pushConstantBytes_, &window);
  vkCmdDispatch(cmd, gx, gy, layers);
}

void DeformationPass::recordStamps(VkCommandBuffer cmd, const WindowConstants& window, std::uint32_t stamps,
                                   glm::ivec2 stampExtent) const {
  dispatch(cmd, stamp_, window, stampExtent, stamps);
}

void DeformationPass::recordNormals(VkCommandBuffer cmd, const WindowConstants& window, std::uint32_t rects,
                                    glm::ivec2 rectExtent) const {
  dispatch(cmd, normals_, window, rectExtent, rects);
}

void DeformationPass::recordRefill(VkCommandBuffer cmd, const WindowConstants& window) const {
  dispatch(cmd, refill_, window, glm::ivec2(window.resolution), 1);
}

void DeformationPass::computeBarrier(VkCommandBuffer cmd) {
  VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  barrier.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
  barrier.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 1, &barrier, 0,
                       nullptr, 0, nullptr);
}

}  // namespace wg::snow
