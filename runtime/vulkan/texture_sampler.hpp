// Vulkan samplers and image formats for textures, from their reflected settings.
#pragma once
#include <string_view>

#include "runtime/vulkan/material_reflection.hpp"
#include "runtime/vulkan/vulkan_context.hpp"
#include "runtime/vulkan/vulkan_handle.hpp"

namespace wg::vk {

// One mip level (maxLod 0), so every read is magnified and uses magFilter, as the CPU
// evaluator does; minFilter is set for completeness. Spellings are the reflection's.
UniqueSampler createSampler(Context& ctx, std::string_view wrapU, std::string_view wrapV, std::string_view minFilter,
                        std::string_view magFilter);
UniqueSampler createSampler(Context& ctx, const ReflectedTexture& texture);

// R8G8B8A8_SRGB for colorSpace "srgb", so the GPU decodes texels to linear before
// filtering; R8G8B8A8_UNORM otherwise.
VkFormat textureFormat(const ReflectedTexture& texture);

}  // namespace wg::vk
