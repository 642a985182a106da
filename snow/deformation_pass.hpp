// The deformation compute pass on Vulkan: five pipelines (stamps, normals, refill, and
// recentring's tile transfers out of and into the map)
// sharing one descriptor set whose layout and push-constant range are built from the
// SPIRV-Cross reflection of the modules (ReflectedDescriptorSet). Buffers are bound by
// their block names.
#pragma once
#include <glm/glm.hpp>

#include <memory>
#include <string>
#include <vector>

#include "vulkan/gpu_buffer.hpp"
#include "vulkan/gpu_image.hpp"
#include "vulkan/reflected_descriptor_set.hpp"

namespace wg::snow {

// Mirrors the push-constant block `Window` of deformation_shaders.cpp; its size is
// checked against the reflected one.
struct WindowConstants {
  std::int32_t origin[2];
  std::int32_t originSlot[2];
  std::int32_t resolution;
  float texelSize;
  std::uint32_t refillQuanta;
};

class DeformationPass {
 public:
  explicit DeformationPass(vk::Context& ctx);
  ~DeformationPass();
  DeformationPass(const DeformationPass&) = delete;
  DeformationPass& operator=(const DeformationPass&) = delete;

  // Points the block named `block` (Heights, Normals, Stamps, StampBoxes, NormalRects, RefillTiles,
  // HostHeights, TransferTiles)
  // at a buffer. Every block must be bound before the first record.
  void bind(const std::string& block, const vk::Buffer& buffer);
  // The surface image the normal stage writes (GENERAL layout while the pass runs).
  void bindSurface(const vk::Image2D& image);

  // Stamp layers, then a barrier, then normal layers; `stampExtent` / `rectExtent` are
  // the largest box and rectangle sizes (texels).
  void recordStamps(VkCommandBuffer cmd, const WindowConstants& window, std::uint32_t stamps,
                    glm::ivec2 stampExtent) const;
  void recordNormals(VkCommandBuffer cmd, const WindowConstants& window, std::uint32_t rects,
                     glm::ivec2 rectExtent) const;
  // One layer per tile of RefillTiles (x, z, tileTexels, quanta).
  void recordRefill(VkCommandBuffer cmd, const WindowConstants& window, std::uint32_t tiles, int tileTexels) const;
  // One layer per tile of TransferTiles (x, z, tileTexels, 0): Heights to HostHeights
  // at the same storage positions, or back.
  void recordTilesOut(VkCommandBuffer cmd, const WindowConstants& window, std::uint32_t tiles, int tileTexels) const;
  void recordTilesIn(VkCommandBuffer cmd, const WindowConstants& window, std::uint32_t tiles, int tileTexels) const;
  static void computeBarrier(VkCommandBuffer cmd);
  enum class Stage { Stamps, Normals, Refill };
  // The invocations a dispatch of `stage` over `layers` layers of `extent` would take.
  std::uint64_t invocationsOf(Stage stage, glm::ivec2 extent, std::uint32_t layers) const;
  // Shader invocations recorded so far: the work of the passes, independent of the
  // device's timing noise (bench-snow reports it per frame).
  std::uint64_t invocations() const { return invocations_; }

 private:
  struct Pipeline {
    vk::UniqueShaderModule module;
    vk::UniquePipeline pipeline;
    std::uint32_t localSize[3] = {1, 1, 1};
  };
  void dispatch(VkCommandBuffer cmd, const Pipeline& p, const WindowConstants& window, glm::ivec2 extent,
                std::uint32_t layers) const;

  vk::Context& ctx_;
  std::unique_ptr<vk::ReflectedDescriptorSet> set_;
  Pipeline stamp_, normals_, refill_, tilesOut_, tilesIn_;
  mutable std::uint64_t invocations_ = 0;
};

}  // namespace wg::snow
