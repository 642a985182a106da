#include "vulkan/gpu_timer.hpp"

namespace wg::vk {

GpuTimer::GpuTimer(Context& ctx) : ctx_(ctx) {
  VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
  info.queryType = VK_QUERY_TYPE_TIMESTAMP;
  info.queryCount = 2;
  VkQueryPool pool;
  check(vkCreateQueryPool(ctx.device(), &info, nullptr, &pool), "vkCreateQueryPool");
  pool_ = UniqueQueryPool(ctx.device(), pool);
}

void GpuTimer::reset(VkCommandBuffer cmd) const { vkCmdResetQueryPool(cmd, pool_.get(), 0, 2); }

void GpuTimer::start(VkCommandBuffer cmd) const {
  vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, pool_.get(), 0);
}

void GpuTimer::stop(VkCommandBuffer cmd) const {
  vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, pool_.get(), 1);
}

double GpuTimer::milliseconds() const {
  std::uint64_t ticks[2] = {0, 0};
  if (vkGetQueryPoolResults(ctx_.device(), pool_.get(), 0, 2, sizeof ticks, ticks, sizeof(std::uint64_t),
                            VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT) != VK_SUCCESS || ticks[1] <= ticks[0])
    return 0.0;
  return double(ticks[1] - ticks[0]) * ctx_.properties().limits.timestampPeriod * 1e-6;
}

}  // namespace wg::vk
