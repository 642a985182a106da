// The deformation height map on the GPU: the window's two texel planes in storage
// buffers, stamped and re-normalled by the compute pass over touched texels only, and
// refilled by a global pass on the frames a refill quantum is due. The normal stage also
// writes the surface image materials sample (snowDeformation: RGBA16F height and world
// normal, toroidal order), so rendering needs no CPU resolve. Recentring and the print
// store run on the CPU over the buffers' mapped memory (every submit here waits, so the
// GPU is idle then); they touch only the tiles that leave or enter, and the surface
// image is redone on the GPU for the tiles that entered.
#pragma once
#include <functional>
#include <memory>
#include <span>
#include <vector>

#include "runtime/snow/deformation_pass.hpp"
#include "runtime/snow/deformation_refill.hpp"
#include "runtime/snow/print_tile_store.hpp"
#include "runtime/snow/snow_stamp.hpp"
#include "runtime/snow/window_recentring.hpp"
#include "runtime/vulkan/gpu_timer.hpp"

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
  // Refill at `metresPerSecond` for `seconds`; dispatches only when a quantum is due.
  // Returns the GPU milliseconds of the refill and its normals (0 when none ran).
  double refill(double metresPerSecond, double seconds);
  Recentring follow(glm::vec2 camera);

  const SnowWindow& window() const { return window_; }
  const PrintTileStore& store() const { return store_; }
  MapTexels texels();
  float depthAt(glm::vec2 world);
  float heightAt(glm::vec2 world);
  glm::vec3 normalAt(glm::vec2 world);

  std::size_t mapBytes() const { return heights_.size() + normals_.size(); }
  // In SHADER_READ_ONLY_OPTIMAL between calls; sample with a repeat sampler at
  // world xz / extent.
  const vk::Image2D& surfaceImage() const { return surface_; }
  const vk::Buffer& heightBuffer() const { return heights_; }
  const vk::Buffer& normalBuffer() const { return normals_; }

 private:
  WindowConstants constants(std::uint32_t refillQuanta) const;
  void reserve(std::size_t stamps);
  // Records `record` between timestamps, with the surface image writable in between.
  double submit(const std::function<void(VkCommandBuffer)>& record);
  // Normals (and the surface image) over `rects`.
  void renormal(const std::vector<TexelRect>& rects);

  vk::Context& ctx_;
  SnowWindow window_;
  DeformationPass pass_;
  vk::Buffer heights_, normals_, stamps_, stampBoxes_, normalRects_;
  vk::Image2D surface_;
  std::size_t capacity_ = 0;
  PrintTileStore store_;
  DeformationRefill refill_;
  vk::GpuTimer timer_;
};

}  // namespace wg::snow
