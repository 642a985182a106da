// A host-visible, coherent buffer: uniforms, vertices, staging. On lavapipe all memory
// is host memory; on a discrete GPU these small buffers stay fast enough.
#pragma once
#include <cstring>

#include "runtime/vulkan/vulkan_context.hpp"

namespace wg::vk {

class Buffer {
 public:
  Buffer() = default;
  Buffer(Context& ctx, VkDeviceSize size, VkBufferUsageFlags usage);
  ~Buffer();
  Buffer(Buffer&& other) noexcept;
  Buffer& operator=(Buffer&& other) noexcept;
  Buffer(const Buffer&) = delete;
  Buffer& operator=(const Buffer&) = delete;

  VkBuffer handle() const { return buffer_; }
  VkDeviceSize size() const { return size_; }
  void* mapped() const { return mapped_; }
  void write(const void* data, VkDeviceSize bytes, VkDeviceSize offset = 0) {
    std::memcpy(static_cast<char*>(mapped_) + offset, data, bytes);
  }

 private:
  void release();
  VkDevice device_ = VK_NULL_HANDLE;
  VkBuffer buffer_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  VkDeviceSize size_ = 0;
  void* mapped_ = nullptr;
};

}  // namespace wg::vk
