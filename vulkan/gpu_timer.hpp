// Two timestamps around recorded work, read after the submit has completed.
#pragma once
#include "vulkan/vulkan_context.hpp"
#include "vulkan/vulkan_handle.hpp"

namespace wg::vk {

class GpuTimer {
 public:
  explicit GpuTimer(Context& ctx);

  void reset(VkCommandBuffer cmd) const;  // before start, outside a render pass
  void start(VkCommandBuffer cmd) const;
  void stop(VkCommandBuffer cmd) const;
  // Between start and stop; 0 when the device reports no usable timestamps.
  double milliseconds() const;

 private:
  Context& ctx_;
  UniqueQueryPool pool_;
};

}  // namespace wg::vk
