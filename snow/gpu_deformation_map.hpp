// The deformation map for weathergen's own renderer, the benchmarks and the tests: the
// DeformationRecorder's commands, each call submitted and waited on (with its GPU time
// measured), so the map can be read back right after. Engines record the same commands
// into their own frames through include/weathergen/snow.hpp instead.
#pragma once
#include <filesystem>
#include <functional>
#include <memory>
#include <span>
#include <vector>

#include "snow/deformation_recorder.hpp"
#include "snow/map_texels.hpp"
#include "vulkan/gpu_timer.hpp"

namespace wg::snow {

class GpuDeformationMap {
 public:
  GpuDeformationMap(vk::Context& ctx, const WindowSettings& settings = {}, glm::vec2 camera = glm::vec2(0.f));
  ~GpuDeformationMap();
  GpuDeformationMap(const GpuDeformationMap&) = delete;
  GpuDeformationMap& operator=(const GpuDeformationMap&) = delete;

  // Stamps, then normals over each stamp's box grown by one texel. Returns the GPU time
  // of both (timestamp queries), in milliseconds; 0 when the queue has no timestamps.
  double apply(std::span<const Stamp> stamps);
  // Meshes drawn from below into the map (mesh_interactor_pass.hpp); GPU milliseconds.
  double applyMeshes(std::span<const MeshInteractor> meshes, const SnowLevel& level);
  // Refill at `metresPerSecond` for `seconds`; dispatches only when a quantum is due.
  // Also the normals of the tiles the last follow() brought in, a few a call
  // (DeformationRecorder::recordDeferredNormals). Returns the GPU milliseconds of
  // both (0 when neither ran).
  double refill(double metresPerSecond, double seconds);
  Recentring follow(glm::vec2 camera);
  // One frame as an engine records it (DeformationRecorder::recordFrame) in one submit:
  // stamps beyond the frame's budget wait for the next frames, and a window move takes
  // two frames (the leaving tiles' copy, then the move). GPU milliseconds.
  double frame(const FrameWork& work);
  std::size_t queuedStamps() const { return recorder_.queuedStamps(); }
  // Shader invocations of every pass so far (the work, without the timing noise).
  std::uint64_t invocations() const { return recorder_.invocations(); }
  // Every print, in the window and in the store, to a file (print_store_file.hpp), and
  // back: loading replaces every print with the file's. Throws PrintFileError.
  void savePrints(const std::filesystem::path& path);
  void loadPrints(const std::filesystem::path& path);

  const SnowWindow& window() const { return recorder_.window(); }
  const PrintTileStore& store() const { return recorder_.store(); }
  // Both planes read back from the device (once per change), in toroidal order, after
  // pressing any queued stamps and finishing any deferred normals (and surface texels).
  MapTexels texels();
  float depthAt(glm::vec2 world);
  float heightAt(glm::vec2 world);
  glm::vec3 normalAt(glm::vec2 world);

  std::size_t mapBytes() const { return recorder_.mapBytes(); }
  // In SHADER_READ_ONLY_OPTIMAL between calls; sample with a repeat sampler at
  // world xz / extent.
  const vk::Image2D& surfaceImage() const { return recorder_.surfaceImage(); }
  const vk::Buffer& heightBuffer() const { return recorder_.heightBuffer(); }
  const vk::Buffer& normalBuffer() const { return recorder_.normalBuffer(); }

 private:
  // Records `record` between timestamps, submits and waits; GPU milliseconds.
  double submit(const std::function<void(VkCommandBuffer)>& record);

  vk::Context& ctx_;
  DeformationRecorder recorder_;
  vk::GpuTimer timer_;
  vk::Buffer hostHeights_, hostNormals_;  // what texels() returns
  bool hostCurrent_ = false;
};

}  // namespace wg::snow
