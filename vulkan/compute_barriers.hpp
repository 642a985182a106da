// The dependencies the runtime's compute passes need: shader writes before the next
// dispatch reads or writes, before the host reads mapped memory, and before a transfer
// copies a buffer into an image as well.
#pragma once
#include <vulkan/vulkan.h>

namespace wg::vk {

void computeToComputeBarrier(VkCommandBuffer cmd);
void computeToHostBarrier(VkCommandBuffer cmd);
void computeToTransferAndHostBarrier(VkCommandBuffer cmd);

}  // namespace wg::vk
