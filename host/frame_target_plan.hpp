// A frame's targets sized against the device before anything is allocated. The
// multisampled colour image is the largest (RGBA16F, 8 bytes a sample); a frame whose
// targets would not fit falls back to fewer MSAA samples, and one that fits at no sample
// count is refused with the largest size that does, instead of failing in
// vkAllocateMemory.
#pragma once
#include <cstdint>
#include <string>

#include "vulkan/vulkan_context.hpp"

namespace wg {

struct FrameLimits {
  std::uint32_t largestSide = 0;        // maxImageDimension2D, maxFramebufferWidth and -Height
  std::uint64_t largestAllocation = 0;  // maxMemoryAllocationSize
  std::uint64_t budget = 0;             // bytes the frame's device-local targets may take together
  unsigned samples = 1;                 // the most MSAA samples the colour pass can have
};

struct FrameTargetPlan {
  unsigned samples = 0;  // MSAA samples per pixel; 0 when the frame fits at none
  // Why fewer samples than asked ("" when as asked), or why nothing fits, with the
  // largest size of the same shape that does.
  std::string note;
};

// The device's limits; the budget is its largest device-local heap. A scene's meshes,
// textures and maps are small next to a frame large enough to meet it.
FrameLimits frameLimits(const vk::Context& ctx);

FrameTargetPlan planFrameTargets(std::uint32_t width, std::uint32_t height, unsigned samples, const FrameLimits& limits);

}  // namespace wg
