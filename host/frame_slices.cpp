#include "host/frame_slices.hpp"

namespace wg {

namespace {
VkDeviceSize alignedStride(vk::Context& ctx, VkDeviceSize size) {
  VkDeviceSize alignment = ctx.properties().limits.minUniformBufferOffsetAlignment;
  return (size + alignment - 1) / alignment * alignment;
}
}  // namespace

FrameSlices::FrameSlices(vk::Context& ctx, const vk::ReflectedBlock& block, std::size_t count)
    : blockSize_(block.size),
      stride_(alignedStride(ctx, block.size)),
      buffer_(ctx, stride_ * count, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT) {}

void FrameSlices::write(std::size_t slice, const FrameUniforms& values) {
  buffer_.write(values.bytes().data(), values.bytes().size(), stride_ * slice);
}

}  // namespace wg
