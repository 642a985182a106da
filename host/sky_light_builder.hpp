// The sky's light for the reference host, rebuilt only when the sky changes:
// - diffuse: one compute dispatch evaluates the shading library's wg_sky (the text the
//   haze pass draws) at the texel centres of a small cube, and the CPU projects that
//   radiance onto spherical harmonics (host/sky_irradiance.hpp);
// - specular: a second dispatch prefilters wg_sky with GGX into a cube map with a
//   roughness per level, the split sum's first factor (Karis 2013), which the surfaces
//   read through wg_sky_reflection.
#pragma once
#include <optional>

#include "host/sky_irradiance.hpp"
#include "host/sky_shader_text.hpp"
#include "vulkan/gpu_buffer.hpp"
#include "vulkan/gpu_image.hpp"
#include "vulkan/reflected_descriptor_set.hpp"

namespace wg {

class SkyLightBuilder {
 public:
  // Texels along a cube face for the diffuse projection: 6 x 32 x 32 directions, far
  // more than nine coefficients need.
  static constexpr std::uint32_t kIrradianceFaceSize = 32;
  // The reflection cube: RGBA16F, 128 x 128 a face at level 0 (under a degree a texel,
  // a mirror's), halved per level down to 4 x 4. Level l holds roughness l / 5: the
  // library's wg_sky_reflection reads level 5 roughness.
  static constexpr std::uint32_t kReflectionFaceSize = 128;
  static constexpr std::uint32_t kReflectionLevels = 6;

  // Makes the reflection cube, black until the first build; compiles its shaders then.
  explicit SkyLightBuilder(vk::Context& ctx);
  ~SkyLightBuilder();
  SkyLightBuilder(const SkyLightBuilder&) = delete;
  SkyLightBuilder& operator=(const SkyLightBuilder&) = delete;

  // The light of the sky `frame` describes (wg_sky's inputs: sky colour, ambient
  // intensity, precipitation, wind): its irradiance, and the reflection cube filled.
  // Submits and waits, so call it outside a command buffer; it dispatches only when
  // those inputs differ from the last call's.
  const SkyIrradiance& lightFor(const FrameState& frame);
  const SkyIrradiance& irradiance() const { return irradiance_; }  // the last one built
  VkImageView reflectionView() const { return reflection_.view(); }
  VkDeviceSize reflectionBytes() const { return reflection_.byteSize(); }
  // A texel of the last reflection built (linear radiance), faces in Vulkan's order.
  glm::vec3 reflectionTexel(std::uint32_t level, std::uint32_t face, std::uint32_t x, std::uint32_t y) const;
  std::size_t builds() const { return builds_; }

 private:
  struct Pipeline {
    std::unique_ptr<vk::ReflectedDescriptorSet> set;
    vk::UniqueShaderModule module;
    vk::UniquePipeline pipeline;
    std::uint32_t localSize = 1;
  };
  Pipeline makePipeline(const std::string& shader, const char* name);
  void record(VkCommandBuffer cmd, const Pipeline& p, const SkyInputs& inputs, std::uint32_t invocations) const;
  void recordReflectionCopy(VkCommandBuffer cmd) const;

  vk::Context& ctx_;
  std::vector<SkySample> samples_;
  vk::Buffer directions_, radiance_, reflectionTexels_;
  vk::Image2D reflection_;
  std::optional<Pipeline> irradiancePipeline_, reflectionPipeline_;  // compiled on the first build
  std::optional<SkyInputs> built_;
  SkyIrradiance irradiance_;
  std::size_t builds_ = 0;
};

}  // namespace wg
