#include "host/frame_recording.hpp"

namespace wg {

namespace {
void setViewport(VkCommandBuffer cmd, std::uint32_t w, std::uint32_t h) {
  VkViewport viewport{0.f, 0.f, float(w), float(h), 0.f, 1.f};
  VkRect2D scissor{{0, 0}, {w, h}};
  vkCmdSetViewport(cmd, 0, 1, &viewport);
  vkCmdSetScissor(cmd, 0, 1, &scissor);
}

void drawIndexed(VkCommandBuffer cmd, const ObjectDraw& d) {
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, d.handle);
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, d.pipeline->layout(), 0, 2, d.sets.data(), 1, &d.frameOffset);
  VkDeviceSize zero = 0;
  VkBuffer vertices = d.mesh->vertices.handle();
  vkCmdBindVertexBuffers(cmd, 0, 1, &vertices, &zero);
  vkCmdBindIndexBuffer(cmd, d.mesh->indices.handle(), 0, VK_INDEX_TYPE_UINT32);
  vkCmdDrawIndexed(cmd, d.mesh->indexCount, 1, 0, 0, 0);
}
}  // namespace

void recordPass(VkCommandBuffer cmd, const PassTarget& target, const std::vector<ObjectDraw>& draws) {
  VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
  begin.renderPass = target.pass;
  begin.framebuffer = target.framebuffer;
  begin.renderArea = {{0, 0}, {target.width, target.height}};
  begin.clearValueCount = static_cast<std::uint32_t>(target.clears.size());
  begin.pClearValues = target.clears.data();
  vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
  setViewport(cmd, target.width, target.height);
  for (const ObjectDraw& d : draws) drawIndexed(cmd, d);
  vkCmdEndRenderPass(cmd);
}

}  // namespace wg
