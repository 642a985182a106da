// Vulkan samplers and image formats for textures, from their reflected settings.
#pragma once
#include <string_view>

#include "vulkan/material_reflection.hpp"
#include "vulkan/vulkan_context.hpp"
#include "vulkan/vulkan_handle.hpp"

namespace wg::vk {

// Which levels of a texture a sampler reads.
enum class MipSampling {
  // Level 0 only (maxLod 0): every read is a bilinear tap of the base level, as the CPU
  // evaluator reads it. The AOV renders that tests compare with it per pixel use this.
  BaseLevel,
  // The whole chain, trilinear (mipmapMode linear, no LOD clamp), and anisotropic (up
  // to 16x) on GPUs that offer it (Context::samplerAnisotropy; never on CPU devices).
  // Lit frames use this.
  FullChain,
};

// Spellings are the reflection's ("repeat", "clamp", "mirror"; "linear", "nearest").
UniqueSampler createSampler(Context& ctx, std::string_view wrapU, std::string_view wrapV, std::string_view minFilter,
                            std::string_view magFilter, MipSampling mips = MipSampling::BaseLevel);
UniqueSampler createSampler(Context& ctx, const ReflectedTexture& texture, MipSampling mips);

// R8G8B8A8_SRGB for colorSpace "srgb", so the GPU decodes texels to linear before
// filtering; R8G8B8A8_UNORM otherwise.
VkFormat textureFormat(const ReflectedTexture& texture);

}  // namespace wg::vk
