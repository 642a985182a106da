// The sky and distance haze (aerial perspective): where the colour pass drew nothing
// (depth 1) it draws the sky the surfaces reflect, with the sun's disc; every surface
// pixel is blended towards that sky's horizon by its distance from the camera, read
// from the colour pass's depth, so far ground fades into the sky and no frame shows
// where the world ends. One compute dispatch on the tone-mapped colour target, after
// the colour pass and before bloom.
#pragma once
#include <glm/glm.hpp>

#include <memory>

#include "host/scene_renderer.hpp"
#include "nodes/frame_state.hpp"
#include "vulkan/reflected_descriptor_set.hpp"

namespace wg {

struct HazeSettings {
  // Metres over which the haze reaches 1 - 1/e (Beer-Lambert extinction): about 3 km
  // visibility (Koschmieder: 3.9 x this), a hazy winter day.
  float distance = 800.f;
  // From this fraction of the far plane the haze also rises smoothly to all sky at the
  // far plane itself, so ground cut off by the far plane leaves no line.
  float horizonFrom = 0.5f;
};

class DistanceHazePass {
 public:
  // sunColor: the sun's radiance at full intensity, as the frame block's sunColor.
  DistanceHazePass(vk::Context& ctx, const glm::vec3& sunColor);
  ~DistanceHazePass();
  DistanceHazePass(const DistanceHazePass&) = delete;
  DistanceHazePass& operator=(const DistanceHazePass&) = delete;

  // The colour target must be in COLOR_ATTACHMENT_OPTIMAL and the depth in
  // DEPTH_STENCIL_ATTACHMENT_OPTIMAL, as RenderRequest::afterColourPass hands them
  // over; both are left there.
  // The sky comes from `frame`, the block the surfaces read: their wg_sky and this one
  // see the same sky colour, weather, sun and exposure.
  void record(const ColourPassTargets& targets, const FrameState& frame, const HazeSettings& settings = {});

 private:
  vk::Context& ctx_;
  std::unique_ptr<vk::ReflectedDescriptorSet> set_;
  vk::UniqueShaderModule module_;
  vk::UniquePipeline pipeline_;
  vk::UniqueSampler depthSampler_;
  std::uint32_t localSize_[2] = {1, 1};
};

}  // namespace wg
