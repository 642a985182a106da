// Precipitation near the viewer (seed 000, ch. 5: snow and rain particles only near the
// observer, at most eight metres away): falling snowflakes and rain streaks in a box
// that follows the camera, drawn over the lit colour pass with a soft depth fade (seed
// 001, 3.3.2). How many of each and how they move comes from the weather conditions
// (weather/precipitation_field.hpp); every particle is derived on the GPU from
// its index and the time, so the same time draws the same particles.
#pragma once
#include <glm/glm.hpp>

#include <memory>

#include "host/colour_overlay.hpp"
#include "host/scene_renderer.hpp"
#include "vulkan/gpu_buffer.hpp"
#include "vulkan/reflected_descriptor_set.hpp"
#include "weather/precipitation_field.hpp"

namespace wg {

// The light the particles are lit by, as the materials are: the sun's radiance
// (colour times intensity), the sky's ambient radiance and the tone curve's exposure.
struct PrecipitationLight {
  glm::vec3 sunRadiance{0.f};
  glm::vec3 skyRadiance{0.f};
  float exposure = 1.f;
};

// The particles' tone-mapped colours (rgb) and opacities (a), as the pass draws them.
struct PrecipitationLook {
  glm::vec4 snow{0.f}, rain{0.f};
};
PrecipitationLook precipitationLook(const PrecipitationLight& light);

class PrecipitationPass {
 public:
  explicit PrecipitationPass(vk::Context& ctx);
  ~PrecipitationPass();
  PrecipitationPass(const PrecipitationPass&) = delete;
  PrecipitationPass& operator=(const PrecipitationPass&) = delete;

  // Draws `field`'s particles at simulated time `seconds` over the colour target. Records
  // nothing when the field is empty. One frame at a time: the previous frame's
  // submit must have completed.
  void record(const ColourPassTargets& targets, const PrecipitationField& field, const PrecipitationLight& light,
              double seconds);

 private:
  vk::Context& ctx_;
  ColourOverlay overlay_;
  vk::Buffer block_;
  std::unique_ptr<vk::ReflectedDescriptorSet> set_;
  vk::UniqueShaderModule vertexModule_, fragmentModule_;
  vk::UniquePipeline pipeline_;
  vk::UniqueSampler depthSampler_;
};

}  // namespace wg
