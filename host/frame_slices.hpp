// The frame block of every (pass, object) in one host-visible uniform buffer: a slice
// each, at offsets aligned for binding as a dynamic uniform buffer.
#pragma once
#include <cstddef>
#include <cstdint>

#include "host/frame_uniforms.hpp"
#include "vulkan/gpu_buffer.hpp"

namespace wg {

class FrameSlices {
 public:
  FrameSlices(vk::Context& ctx, const vk::ReflectedBlock& block, std::size_t count);

  void write(std::size_t slice, const FrameUniforms& values);
  std::uint32_t offset(std::size_t slice) const { return static_cast<std::uint32_t>(stride_ * slice); }
  VkBuffer buffer() const { return buffer_.handle(); }
  VkDeviceSize blockSize() const { return blockSize_; }  // the range each binding sees

 private:
  VkDeviceSize blockSize_, stride_;
  vk::Buffer buffer_;
};

}  // namespace wg
