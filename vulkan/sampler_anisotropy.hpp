// How much anisotropic filtering a device's lit-frame samplers use.
#pragma once
#include <vulkan/vulkan.h>

#include <algorithm>

namespace wg::vk {

// The most anisotropic filtering asked of any device.
inline constexpr float kMaxSamplerAnisotropy = 16.f;

// The maxAnisotropy for full-chain samplers on a device of `type` that offers the
// samplerAnisotropy feature (`offered`) with limits.maxSamplerAnisotropy `deviceLimit`;
// 1 means anisotropic filtering is off and samplers are trilinear only.
// GPUs filter anisotropically, up to 16x. CPU devices do not: lavapipe's anisotropic
// path takes minutes for low, grazing views (the valley's river camera at 64x36: over
// 5 minutes at 16x or 4x, 2.4 s trilinear), which looks like a hang.
constexpr float samplerAnisotropyFor(VkPhysicalDeviceType type, bool offered, float deviceLimit) {
  if (!offered || type == VK_PHYSICAL_DEVICE_TYPE_CPU) return 1.f;
  return std::clamp(deviceLimit, 1.f, kMaxSamplerAnisotropy);
}

}  // namespace wg::vk
