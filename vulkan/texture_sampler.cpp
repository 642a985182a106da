#include "vulkan/texture_sampler.hpp"

namespace wg::vk {

namespace {
VkSamplerAddressMode addressMode(std::string_view wrap) {
  if (wrap == "clamp") return VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  if (wrap == "mirror") return VK_SAMPLER_ADDRESS_MODE_MIRRORED_REPEAT;
  return VK_SAMPLER_ADDRESS_MODE_REPEAT;
}
VkFilter filterMode(std::string_view filter) { return filter == "nearest" ? VK_FILTER_NEAREST : VK_FILTER_LINEAR; }
}  // namespace

UniqueSampler createSampler(Context& ctx, std::string_view wrapU, std::string_view wrapV, std::string_view minFilter,
                            std::string_view magFilter, MipSampling mips) {
  VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  info.minFilter = filterMode(minFilter);
  info.magFilter = filterMode(magFilter);
  info.addressModeU = addressMode(wrapU);
  info.addressModeV = info.addressModeW = addressMode(wrapV);
  if (mips == MipSampling::FullChain) {
    info.mipmapMode = VK_SAMPLER_MIPMAP_MODE_LINEAR;
    info.maxLod = VK_LOD_CLAMP_NONE;
    const bool linear = info.minFilter == VK_FILTER_LINEAR && info.magFilter == VK_FILTER_LINEAR;
    if (linear && ctx.samplerAnisotropy() > 1.f) {
      info.anisotropyEnable = VK_TRUE;
      info.maxAnisotropy = ctx.samplerAnisotropy();
    }
  } else {
    info.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
    info.maxLod = 0.f;  // level 0, as the CPU evaluator samples
  }
  VkSampler sampler;
  check(vkCreateSampler(ctx.device(), &info, nullptr, &sampler), "vkCreateSampler");
  return UniqueSampler(ctx.device(), sampler);
}

UniqueSampler createSampler(Context& ctx, const ReflectedTexture& t, MipSampling mips) {
  return createSampler(ctx, t.wrapU, t.wrapV, t.minFilter, t.magFilter, mips);
}

VkFormat textureFormat(const ReflectedTexture& t) {
  return t.colorSpace == "srgb" ? VK_FORMAT_R8G8B8A8_SRGB : VK_FORMAT_R8G8B8A8_UNORM;
}

}  // namespace wg::vk
