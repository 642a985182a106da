// A host-visible, coherent buffer: uniforms, vertices, staging. On lavapipe all memory
// is host memory; on a discrete GPU these small buffers stay fast enough. Buffers only
// the GPU touches (the snow map) ask for device-local memory instead: not mapped.
#pragma once
#include <cstring>

#include "vulkan/vulkan_context.hpp"
#include "vulkan/vulkan_handle.hpp"

namespace wg::vk {

enum class BufferMemory : std::uint8_t { HostVisible, DeviceLocal };

class Buffer {
 public:
  Buffer() = default;
  Buffer(Context& ctx, VkDeviceSize size, VkBufferUsageFlags usage, BufferMemory memory = BufferMemory::HostVisible);
  Buffer(Buffer&& other) noexcept;
  Buffer& operator=(Buffer&& other) noexcept;

  VkBuffer handle() const { return buffer_.get(); }
  VkDeviceSize size() const { return size_; }
  void* mapped() const { return mapped_; }  // null for device-local memory
  void write(const void* data, VkDeviceSize bytes, VkDeviceSize offset = 0) {
    std::memcpy(static_cast<char*>(mapped_) + offset, data, bytes);
  }

 private:
  UniqueDeviceMemory memory_;  // stays mapped: freeing it unmaps it
  UniqueBuffer buffer_;        // destroyed before its memory
  VkDeviceSize size_ = 0;
  void* mapped_ = nullptr;
};

}  // namespace wg::vk
