#include "snow/gpu_deformation_map.hpp"

#include "snow/deformation_texel.hpp"
#include "snow/map_lookup.hpp"
#include "snow/print_store_file.hpp"

namespace wg::snow {

GpuDeformationMap::GpuDeformationMap(vk::Context& ctx, const WindowSettings& settings, glm::vec2 camera)
    : ctx_(ctx), recorder_(ctx, settings, camera, 1), timer_(ctx) {
  // The first recording clears the map and the surface image.
  submit([&](VkCommandBuffer cmd) { recorder_.recordStamps(cmd, {}); });
}

GpuDeformationMap::~GpuDeformationMap() { vkDeviceWaitIdle(ctx_.device()); }

double GpuDeformationMap::submit(const std::function<void(VkCommandBuffer)>& record) {
  recorder_.beginFrame(0);  // every earlier submit has completed
  hostCurrent_ = false;
  ctx_.submitAndWait([&](VkCommandBuffer cmd) {
    timer_.reset(cmd);
    timer_.start(cmd);
    record(cmd);
    timer_.stop(cmd);
  });
  return timer_.milliseconds();
}

double GpuDeformationMap::apply(std::span<const Stamp> stamps) {
  return submit([&](VkCommandBuffer cmd) { recorder_.recordStamps(cmd, stamps); });
}

double GpuDeformationMap::applyMeshes(std::span<const MeshInteractor> meshes, const SnowLevel& level) {
  return submit([&](VkCommandBuffer cmd) { recorder_.recordMeshes(cmd, meshes, level); });
}

double GpuDeformationMap::refill(double metresPerSecond, double seconds) {
  bool ran = false;
  double ms = submit([&](VkCommandBuffer cmd) {
    ran = recorder_.recordRefill(cmd, metresPerSecond, seconds);
    ran = recorder_.recordDeferredNormals(cmd) || ran;
  });
  return ran ? ms : 0.0;
}

Recentring GpuDeformationMap::follow(glm::vec2 camera) {
  if (window().originFor(camera) == window().origin()) return {};
  // The first submit copies the heights out, the second (its copy complete) moves the
  // window and uploads the tiles that entered.
  double copyOut = submit([&](VkCommandBuffer cmd) { recorder_.recordFollow(cmd, camera); });
  Recentring r;
  double upload = submit([&](VkCommandBuffer cmd) { r = recorder_.recordFollow(cmd, camera); });
  if (r.moved()) r.gpuMilliseconds = copyOut + upload;
  return r;
}

double GpuDeformationMap::frame(const FrameWork& work) {
  return submit([&](VkCommandBuffer cmd) { recorder_.recordFrame(cmd, work); });
}

void GpuDeformationMap::savePrints(const std::filesystem::path& path) {
  savePrintsFile(path, recorder_.prints(texels().heights), window(), recorder_.refillQuanta());
}

void GpuDeformationMap::loadPrints(const std::filesystem::path& path) {
  PrintTileStore loaded(store().budgetBytes());
  loadPrintsFile(path, window(), recorder_.refillQuanta(), loaded);  // throws before anything changes
  submit([&](VkCommandBuffer cmd) { recorder_.recordLoadPrints(cmd, std::move(loaded)); });
}

MapTexels GpuDeformationMap::texels() {
  std::size_t count = window().texelCount();
  if (recorder_.deferredNormals() != 0 || recorder_.queuedStamps() != 0)  // a complete map
    submit([&](VkCommandBuffer cmd) {
      recorder_.recordQueuedStamps(cmd);
      recorder_.recordDeferredNormals(cmd, recorder_.deferredNormals());
    });
  if (!hostCurrent_) {
    VkDeviceSize bytes = count * sizeof(std::uint32_t);
    if (!hostHeights_.handle()) {
      hostHeights_ = vk::Buffer(ctx_, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
      hostNormals_ = vk::Buffer(ctx_, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    }
    ctx_.submitAndWait([&](VkCommandBuffer cmd) {
      DeformationRecorder::recordReadBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT);
      VkBufferCopy all{0, 0, bytes};
      vkCmdCopyBuffer(cmd, heightBuffer().handle(), hostHeights_.handle(), 1, &all);
      vkCmdCopyBuffer(cmd, normalBuffer().handle(), hostNormals_.handle(), 1, &all);
      VkMemoryBarrier toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
      toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
      toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
      vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &toHost, 0, nullptr, 0,
                           nullptr);
    });
    hostCurrent_ = true;
  }
  return {{static_cast<std::uint32_t*>(hostHeights_.mapped()), count},
          {static_cast<std::uint32_t*>(hostNormals_.mapped()), count}};
}

float GpuDeformationMap::depthAt(glm::vec2 world) { return texelDepth(heightTexelAt(window(), texels().heights, world)); }
float GpuDeformationMap::heightAt(glm::vec2 world) { return texelHeight(heightTexelAt(window(), texels().heights, world)); }
glm::vec3 GpuDeformationMap::normalAt(glm::vec2 world) { return snow::normalAt(window(), texels().normals, world); }

}  // namespace wg::snow
