// Snow puffs (seed 3.3): small clouds of snow kicked up at every
// footfall. Particles live in a GPU buffer; a compute pass moves them (gravity, air drag
// towards the wind) and ages them; they are drawn as camera-facing billboards that fade
// softly where they meet the scene (seed 3.3.2, soft particles). The scene depth is read
// as the D32 float it was rendered to: the seed had to pack depth into two 8-bit
// channels (eq. 3.1-3.4) and found 8 bits too coarse.
#pragma once
#include <glm/glm.hpp>

#include <memory>
#include <span>

#include "host/colour_overlay.hpp"
#include "host/scene_renderer.hpp"
#include "vulkan/reflected_descriptor_set.hpp"

namespace wg::snow {

// Mirrors `Particle` in snow_puff_shaders.cpp (std430).
struct Particle {
  glm::vec4 positionAge{0.f};   // xyz world position, w age (s)
  glm::vec4 velocityLife{0.f};  // xyz velocity (m/s), w lifetime (s); 0 = free slot
  glm::vec4 sizeShade{0.f};     // x billboard radius (m), y albedo, z the surface height it left
};

struct PuffSettings {
  std::uint32_t capacity = 4096;  // a ring: the oldest puffs give way
  int particlesPerFootfall = 32;
  float lifetime = 1.2f;          // s, +-30 % per particle (or until it lands)
  float launchSpeed = 5.f;        // m/s, mostly up and out
  float radius = 0.1f;            // m
  float gravity = 9.81f;
  // 1/s, linear air drag: kicked-up snow is stopped within ~half a metre and settles
  // at g / drag ~ 1.2 m/s, about the fall speed of snowflakes and small clumps.
  float drag = 8.f;
  float softness = 0.25f;         // m: depth difference over which a puff fades into the snow
  // The light on a puff, in the colour target's display terms (it is drawn after tone
  // mapping): fully sunlit it reaches sky + sun, kept under the sunlit snow's ~0.88 so
  // a puff never outshines the snow it was kicked from or clips to white after bloom.
  glm::vec3 towardsSun{0.f, 1.f, 0.f};
  float sunLight = 0.3f;
  float skyLight = 0.52f;  // all round, a little blue
};

class SnowPuffs {
 public:
  SnowPuffs(vk::Context& ctx, const PuffSettings& settings = {});
  ~SnowPuffs();
  SnowPuffs(const SnowPuffs&) = delete;
  SnowPuffs& operator=(const SnowPuffs&) = delete;

  // A puff at each footfall (world positions on the snow surface).
  void emit(std::span<const glm::vec3> footfalls);
  // Moves every particle by `seconds` on the GPU (one compute dispatch, waits).
  void simulate(double seconds, glm::vec2 wind);
  // Draws the live particles into the colour target, fading against its depth.
  void record(const ColourPassTargets& targets);

  std::span<const Particle> particles() const;  // mapped: valid between submits
  std::size_t live() const;

 private:
  vk::Context& ctx_;
  PuffSettings settings_;
  ColourOverlay overlay_;  // the render pass, before the pipeline made for it
  vk::Buffer particles_;
  std::uint32_t next_ = 0, emitted_ = 0;
  std::unique_ptr<vk::ReflectedDescriptorSet> simulateSet_, drawSet_;
  vk::UniqueShaderModule simulateModule_, vertexModule_, fragmentModule_;
  vk::UniquePipeline simulatePipeline_, drawPipeline_;
  vk::UniqueSampler depthSampler_;
  std::uint32_t simulateLocalSize_ = 1;
};

}  // namespace wg::snow
