// Descriptor sets of the scene's materials: set 0 (the frame slice and the shared
// maps) and set 1 (the material block and textures), laid out as each material's
// reflection says. Writes are queued and applied in one vkUpdateDescriptorSets.
#pragma once
#include <array>
#include <memory>
#include <vector>

#include "host/material_resources.hpp"
#include "vulkan/vulkan_handle.hpp"

namespace wg {

// Queued descriptor writes; the infos they point at live as long as the writer.
struct DescriptorWriter {
  std::vector<VkWriteDescriptorSet> writes;
  std::vector<std::unique_ptr<VkDescriptorImageInfo>> images;
  std::vector<std::unique_ptr<VkDescriptorBufferInfo>> buffers;

  void buffer(VkDescriptorSet set, std::uint32_t binding, VkDescriptorType type, VkBuffer buffer, VkDeviceSize range) {
    buffers.push_back(std::make_unique<VkDescriptorBufferInfo>(VkDescriptorBufferInfo{buffer, 0, range}));
    add(set, binding, type).pBufferInfo = buffers.back().get();
  }
  void image(VkDescriptorSet set, std::uint32_t binding, VkImageView view) {
    images.push_back(std::make_unique<VkDescriptorImageInfo>(
        VkDescriptorImageInfo{VK_NULL_HANDLE, view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL}));
    add(set, binding, VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE).pImageInfo = images.back().get();
  }
  void sampler(VkDescriptorSet set, std::uint32_t binding, VkSampler sampler) {
    images.push_back(std::make_unique<VkDescriptorImageInfo>(VkDescriptorImageInfo{sampler, VK_NULL_HANDLE, VK_IMAGE_LAYOUT_UNDEFINED}));
    add(set, binding, VK_DESCRIPTOR_TYPE_SAMPLER).pImageInfo = images.back().get();
  }
  void apply(VkDevice device) const {
    vkUpdateDescriptorSets(device, static_cast<std::uint32_t>(writes.size()), writes.data(), 0, nullptr);
  }

 private:
  VkWriteDescriptorSet& add(VkDescriptorSet set, std::uint32_t binding, VkDescriptorType type) {
    VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    w.dstSet = set;
    w.dstBinding = binding;
    w.descriptorCount = 1;
    w.descriptorType = type;
    writes.push_back(w);
    return writes.back();
  }
};

// The images a pass binds for the shared maps.
struct SharedMaps {
  VkImageView terrainHeight, skyExposure, sunShadow, snowDeformation;
  VkImageView weatherNoise;   // the shared noise texture (nodes/weather_noise.hpp)
  VkImageView skyReflection;  // the prefiltered sky, a cube (host/sky_light_builder.hpp)
  VkSampler linear, nearest;  // depth formats need not be filterable; PCF filters
  VkSampler repeat;           // the toroidal snow deformation map and the tiling noise
  VkSampler trilinear;        // every level: the sky reflection's roughness
  // The materials' textures read at level 0 only (AOVs: as the CPU evaluator reads
  // them), not through their mip chains.
  bool baseLevelTextures = false;
};

// A pool for `sets` sets: `uniformBuffers` of each uniform kind (dynamic and plain),
// `images` sampled images and as many samplers.
vk::UniqueDescriptorPool createMaterialDescriptorPool(VkDevice device, std::uint32_t sets, std::uint32_t uniformBuffers,
                                                      std::uint32_t images);

// Allocates one object's set 0 (frame slice and shared maps) and set 1 (material)
// and queues their writes.
std::array<VkDescriptorSet, 2> allocateMaterialSets(VkDevice device, VkDescriptorPool pool, const MaterialResources& material,
                                                    const vk::MaterialPipeline& pipeline, DescriptorWriter& writer,
                                                    VkBuffer frameBuffer, VkDeviceSize frameSize, const SharedMaps& maps);

}  // namespace wg
