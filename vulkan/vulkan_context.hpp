// A headless Vulkan 1.1 device: instance, physical-device choice, one graphics queue,
// a command pool, and (optionally) the validation layers with every message counted.
#pragma once
#include <vulkan/vulkan.h>

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "vulkan/vulkan_handle.hpp"

namespace wg::vk {

struct ContextOptions {
  // "" picks the first device, preferring a CPU device (lavapipe) for reproducibility;
  // "cpu", "integrated", "discrete" pick by type; anything else matches the name.
  std::string device;
  bool validation = false;
};

class Context {
 public:
  // Returns null and sets error when no usable device exists.
  static std::unique_ptr<Context> create(const ContextOptions& options, std::string& error);
  // Wraps a device an engine created and keeps: nothing is destroyed or waited on when
  // it goes, it has no command pool (submitAndWait is unavailable), and
  // `fragmentStoresAndAtomics` says whether the engine enabled that feature.
  static std::unique_ptr<Context> borrow(VkPhysicalDevice physical, VkDevice device, std::uint32_t queueFamily,
                                         bool fragmentStoresAndAtomics);
  ~Context();
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  VkInstance instance() const { return instance_.get(); }
  VkPhysicalDevice physicalDevice() const { return physical_; }
  VkDevice device() const { return device_.get(); }
  VkQueue queue() const { return queue_; }
  std::uint32_t queueFamily() const { return queueFamily_; }
  VkCommandPool commandPool() const { return commandPool_.get(); }
  const VkPhysicalDeviceProperties& properties() const { return properties_; }
  std::string deviceName() const { return properties_.deviceName; }
  bool validationEnabled() const { return static_cast<bool>(messenger_); }
  // Optional capabilities, enabled at device creation where the device has them:
  // anisotropic texture filtering (GPUs only: see samplerAnisotropyFor), and
  // VK_KHR_depth_stencil_resolve (with VK_KHR_create_renderpass2), which a
  // multisampled colour pass resolves its depth with.
  // The maxAnisotropy of full-chain samplers; 1 when anisotropic filtering is off.
  float samplerAnisotropy() const { return samplerAnisotropy_; }
  bool depthStencilResolve() const { return depthStencilResolve_; }
  // Storage writes and atomics from fragment shaders (the snow's mesh interactors).
  bool fragmentStoresAndAtomics() const { return fragmentStoresAndAtomics_; }

  // Validation messages (warnings and errors) seen so far.
  const std::vector<std::string>& validationMessages() const { return messages_; }
  void clearValidationMessages() { messages_.clear(); }

  // The most bytes one allocation may hold (maxMemoryAllocationSize) and the size of
  // the largest device-local heap, for callers that size large images before allocating.
  struct MemoryLimits {
    VkDeviceSize largestAllocation = 0, deviceLocalHeap = 0;
  };
  MemoryLimits memoryLimits() const;

  // Memory type with all of `flags` among `typeBits`; UINT32_MAX when none.
  std::uint32_t findMemoryType(std::uint32_t typeBits, VkMemoryPropertyFlags flags) const;

  // Records commands into a fresh command buffer, submits and waits.
  template <typename Record>
  void submitAndWait(Record&& record) {
    UniqueCommandBuffer cmd = beginOneTime();
    record(cmd.get());
    endOneTime(cmd.get());
  }

  static std::vector<std::string> listDevices(std::string& error);

 private:
  Context() = default;
  // The steps of create(); each sets `error` and returns false on failure.
  bool attachMessenger(std::string& error);
  bool choosePhysicalDevice(const std::string& selector, std::string& error);
  bool createDevice(std::string& error);
  UniqueCommandBuffer beginOneTime();
  void endOneTime(VkCommandBuffer cmd);
  static VKAPI_ATTR VkBool32 VKAPI_CALL onMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                  VkDebugUtilsMessageTypeFlagsEXT types,
                                                  const VkDebugUtilsMessengerCallbackDataEXT* data, void* user);

  // Destroyed bottom-up: the pool, the device, the messenger, the instance. The
  // messenger may still report while the device goes, so messages_ outlives it.
  std::vector<std::string> messages_;
  UniqueInstance instance_;
  UniqueDebugMessenger messenger_;
  VkPhysicalDevice physical_ = VK_NULL_HANDLE;
  UniqueDevice device_;
  VkQueue queue_ = VK_NULL_HANDLE;
  std::uint32_t queueFamily_ = 0;
  UniqueCommandPool commandPool_;
  VkPhysicalDeviceProperties properties_{};
  VkPhysicalDeviceMemoryProperties memory_{};
  float samplerAnisotropy_ = 1.f;
  bool depthStencilResolve_ = false, fragmentStoresAndAtomics_ = false;
  bool borrowed_ = false;
};

// A Vulkan call ran out of device or host memory: a resource limit the input met (a
// frame or texture too large), not a bug.
class OutOfMemory : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Throws OutOfMemory, or std::runtime_error for any other failure, naming the call when
// a Vulkan call fails.
void check(VkResult result, const char* what);

}  // namespace wg::vk
