// The two dependencies the runtime's compute passes need: shader writes before the
// next dispatch reads or writes, and before the host reads mapped memory.
#pragma once
#include <vulkan/vulkan.h>

namespace wg::vk {

void computeToComputeBarrier(VkCommandBuffer cmd);
void computeToHostBarrier(VkCommandBuffer cmd);

}  // namespace wg::vk
