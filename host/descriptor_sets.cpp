#include "host/descriptor_sets.hpp"

namespace wg {

vk::UniqueDescriptorPool createMaterialDescriptorPool(VkDevice device, std::uint32_t sets, std::uint32_t uniformBuffers,
                                                      std::uint32_t images) {
  VkDescriptorPoolSize sizes[] = {
      {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, uniformBuffers},
      {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, uniformBuffers},
      {VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE, images},
      {VK_DESCRIPTOR_TYPE_SAMPLER, images},
  };
  VkDescriptorPoolCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  info.maxSets = sets;
  info.poolSizeCount = 4;
  info.pPoolSizes = sizes;
  VkDescriptorPool pool;
  vk::check(vkCreateDescriptorPool(device, &info, nullptr, &pool), "vkCreateDescriptorPool");
  return vk::UniqueDescriptorPool(device, pool);
}

std::array<VkDescriptorSet, 2> allocateMaterialSets(VkDevice device, VkDescriptorPool pool, const MaterialResources& material,
                                                    const vk::MaterialPipeline& pipeline, DescriptorWriter& writer,
                                                    VkBuffer frameBuffer, VkDeviceSize frameSize, const SharedMaps& maps) {
  VkDescriptorSetLayout layouts[2] = {pipeline.setLayout(0), pipeline.setLayout(1)};
  VkDescriptorSetAllocateInfo alloc{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  alloc.descriptorPool = pool;
  alloc.descriptorSetCount = 2;
  alloc.pSetLayouts = layouts;
  std::array<VkDescriptorSet, 2> sets{};
  vk::check(vkAllocateDescriptorSets(device, &alloc, sets.data()), "vkAllocateDescriptorSets");
  const auto& refl = material.reflection();
  writer.buffer(sets[0], refl.frame.binding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, frameBuffer, frameSize);
  for (const auto& map : refl.weatherMaps) {
    bool shadow = map.name == "sunShadow", deformation = map.name == "snowDeformation", noise = map.name == "weatherNoise",
         sky = map.name == "skyReflection";
    writer.image(sets[0], map.binding,
                 map.name == "terrainHeight" ? maps.terrainHeight
                 : shadow                    ? maps.sunShadow
                 : deformation               ? maps.snowDeformation
                 : noise                     ? maps.weatherNoise
                 : sky                       ? maps.skyReflection
                                             : maps.skyExposure);
    writer.sampler(sets[0], map.samplerBinding,
                   shadow ? maps.nearest : deformation || noise ? maps.repeat : sky ? maps.trilinear : maps.linear);
  }
  if (const vk::Buffer* params = material.parameterBuffer())
    writer.buffer(sets[1], refl.material.binding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, params->handle(), refl.material.size);
  for (const auto& t : material.textures()) {
    writer.image(sets[1], t.reflected->binding, t.image.view());
    writer.sampler(sets[1], t.reflected->samplerBinding, t.samplerFor(maps.baseLevelTextures));
  }
  return sets;
}

}  // namespace wg
