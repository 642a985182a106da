#include "vulkan/gpu_buffer.hpp"

#include <stdexcept>
#include <utility>

namespace wg::vk {

Buffer::Buffer(Context& ctx, VkDeviceSize size, VkBufferUsageFlags usage, BufferMemory kind) : size_(size) {
  VkDevice device = ctx.device();
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = size;
  info.usage = usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  VkBuffer buffer;
  check(vkCreateBuffer(device, &info, nullptr, &buffer), "vkCreateBuffer");
  buffer_ = UniqueBuffer(device, buffer);
  VkMemoryRequirements req;
  vkGetBufferMemoryRequirements(device, buffer, &req);
  VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  alloc.allocationSize = req.size;
  bool hostVisible = kind == BufferMemory::HostVisible;
  alloc.memoryTypeIndex = ctx.findMemoryType(req.memoryTypeBits, hostVisible ? VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT |
                                                                                    VK_MEMORY_PROPERTY_HOST_COHERENT_BIT
                                                                              : VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
  if (alloc.memoryTypeIndex == UINT32_MAX)
    throw std::runtime_error(hostVisible ? "no host-visible memory for a buffer" : "no device-local memory for a buffer");
  VkDeviceMemory memory;
  check(vkAllocateMemory(device, &alloc, nullptr, &memory), "vkAllocateMemory");
  memory_ = UniqueDeviceMemory(device, memory);
  check(vkBindBufferMemory(device, buffer, memory, 0), "vkBindBufferMemory");
  if (hostVisible) check(vkMapMemory(device, memory, 0, VK_WHOLE_SIZE, 0, &mapped_), "vkMapMemory");
}

Buffer::Buffer(Buffer&& o) noexcept { *this = std::move(o); }

Buffer& Buffer::operator=(Buffer&& o) noexcept {
  if (this != &o) {
    buffer_ = std::move(o.buffer_);  // before its new memory frees the old
    memory_ = std::move(o.memory_);
    size_ = std::exchange(o.size_, 0);
    mapped_ = std::exchange(o.mapped_, nullptr);
  }
  return *this;
}

}  // namespace wg::vk
