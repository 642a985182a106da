// The one owner of Vulkan objects: a move-only handle that destroys its object with
// the matching vkDestroy* (or vkFree*) call when it goes. Objects created on a device
// keep that device; instances and devices destroy themselves. Members of a class go in
// reverse declaration order, so declare what an object depends on (memory, layouts,
// render passes) before it.
#pragma once
#include <vulkan/vulkan.h>

#include <type_traits>
#include <utility>

namespace wg::vk {

// Stands for "no parent" in Handle: the object is destroyed with Destroy(handle, nullptr).
struct NoParent {};

template <typename T, auto Destroy, typename Parent = VkDevice>
class Handle {
 public:
  Handle() = default;
  Handle(Parent parent, T handle) noexcept : parent_(parent), handle_(handle) {}
  explicit Handle(T handle) noexcept requires std::is_same_v<Parent, NoParent> : handle_(handle) {}
  ~Handle() { reset(); }
  Handle(Handle&& other) noexcept : parent_(other.parent_), handle_(std::exchange(other.handle_, T{})) {}
  Handle& operator=(Handle&& other) noexcept {
    if (this != &other) {
      reset();
      parent_ = other.parent_;
      handle_ = std::exchange(other.handle_, T{});
    }
    return *this;
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;

  T get() const { return handle_; }
  explicit operator bool() const { return handle_ != T{}; }
  // Gives the object up without destroying it (a device an engine owns).
  T release() noexcept { return std::exchange(handle_, T{}); }
  void reset() noexcept {
    if (handle_ == T{}) return;
    if constexpr (std::is_same_v<Parent, NoParent>) Destroy(handle_, nullptr);
    else Destroy(parent_, handle_, nullptr);
    handle_ = T{};
  }

 private:
  [[no_unique_address]] Parent parent_{};
  T handle_{};
};

// What frees a command buffer: its device and pool.
struct CommandPoolOf {
  VkDevice device = VK_NULL_HANDLE;
  VkCommandPool pool = VK_NULL_HANDLE;
};

// Shaped like vkDestroy*, for the two objects Vulkan destroys differently.
void freeCommandBuffer(CommandPoolOf owner, VkCommandBuffer cmd, const VkAllocationCallbacks* allocator);
void destroyDebugMessenger(VkInstance instance, VkDebugUtilsMessengerEXT messenger, const VkAllocationCallbacks* allocator);

using UniqueInstance = Handle<VkInstance, vkDestroyInstance, NoParent>;
using UniqueDevice = Handle<VkDevice, vkDestroyDevice, NoParent>;
using UniqueDebugMessenger = Handle<VkDebugUtilsMessengerEXT, destroyDebugMessenger, VkInstance>;
using UniqueCommandPool = Handle<VkCommandPool, vkDestroyCommandPool>;
using UniqueCommandBuffer = Handle<VkCommandBuffer, freeCommandBuffer, CommandPoolOf>;
using UniqueDeviceMemory = Handle<VkDeviceMemory, vkFreeMemory>;
using UniqueBuffer = Handle<VkBuffer, vkDestroyBuffer>;
using UniqueImage = Handle<VkImage, vkDestroyImage>;
using UniqueImageView = Handle<VkImageView, vkDestroyImageView>;
using UniqueSampler = Handle<VkSampler, vkDestroySampler>;
using UniqueShaderModule = Handle<VkShaderModule, vkDestroyShaderModule>;
using UniqueDescriptorSetLayout = Handle<VkDescriptorSetLayout, vkDestroyDescriptorSetLayout>;
using UniqueDescriptorPool = Handle<VkDescriptorPool, vkDestroyDescriptorPool>;  // frees its sets
using UniquePipelineLayout = Handle<VkPipelineLayout, vkDestroyPipelineLayout>;
using UniquePipeline = Handle<VkPipeline, vkDestroyPipeline>;
using UniqueRenderPass = Handle<VkRenderPass, vkDestroyRenderPass>;
using UniqueFramebuffer = Handle<VkFramebuffer, vkDestroyFramebuffer>;
using UniqueQueryPool = Handle<VkQueryPool, vkDestroyQueryPool>;

}  // namespace wg::vk
