// Bloom (seed 001, 3.5.1 after Ueda et al.): the brightest pixels are extracted at half
// resolution, blurred with a separable Gaussian and added back, so snow in full sun and
// its glitter glow. Four compute dispatches on the colour target; the descriptor layout
// comes from the modules' reflection.
#pragma once
#include <memory>

#include "vulkan/gpu_image.hpp"
#include "vulkan/reflected_descriptor_set.hpp"

namespace wg {

struct BloomSettings {
  // The colour target holds tone-mapped linear values in [0, 1]; sunlit snow sits near
  // 0.75, so it glows a little and its glitter a lot (seed 3.5.1: "the feeling of
  // being in a very bright environment"). Chosen for looks.
  float threshold = 0.6f;
  float intensity = 0.6f;
};

class BloomPass {
 public:
  explicit BloomPass(vk::Context& ctx);
  ~BloomPass();
  BloomPass(const BloomPass&) = delete;
  BloomPass& operator=(const BloomPass&) = delete;

  // `colour` must be a storage-capable RGBA32F image in COLOR_ATTACHMENT_OPTIMAL; it is
  // left there.
  void record(VkCommandBuffer cmd, const vk::Image2D& colour, const BloomSettings& settings = {});

 private:
  struct Stage {
    vk::UniqueShaderModule module;
    vk::UniquePipeline pipeline;
    std::uint32_t localSize[2] = {1, 1};
  };
  vk::Context& ctx_;
  std::unique_ptr<vk::ReflectedDescriptorSet> set_;
  Stage bright_, blurH_, blurV_, composite_;
  vk::Image2D halfA_, halfB_;
};

}  // namespace wg
