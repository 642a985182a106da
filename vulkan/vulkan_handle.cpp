#include "vulkan/vulkan_handle.hpp"

namespace wg::vk {

void freeCommandBuffer(CommandPoolOf owner, VkCommandBuffer cmd, const VkAllocationCallbacks*) {
  vkFreeCommandBuffers(owner.device, owner.pool, 1, &cmd);
}

void destroyDebugMessenger(VkInstance instance, VkDebugUtilsMessengerEXT messenger, const VkAllocationCallbacks* allocator) {
  // An extension entry point: the loader exports no prototype for it.
  auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
      vkGetInstanceProcAddr(instance, "vkDestroyDebugUtilsMessengerEXT"));
  if (destroy) destroy(instance, messenger, allocator);
}

}  // namespace wg::vk
