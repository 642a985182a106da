// The sky's diffuse light for the frame block, rebuilt only when the sky changes. One
// compute dispatch evaluates the shading library's wg_sky (the text the surfaces
// reflect and the haze pass draws) at the texel centres of a small cube; the CPU
// projects that radiance onto spherical harmonics (host/sky_irradiance.hpp).
#pragma once
#include <optional>

#include "host/sky_irradiance.hpp"
#include "host/sky_shader_text.hpp"
#include "vulkan/gpu_buffer.hpp"
#include "vulkan/reflected_descriptor_set.hpp"

namespace wg {

class SkyIrradianceBuilder {
 public:
  // Texels along a cube face: 6 x 32 x 32 directions, far more than nine coefficients need.
  static constexpr std::uint32_t kFaceSize = 32;

  explicit SkyIrradianceBuilder(vk::Context& ctx);
  ~SkyIrradianceBuilder();
  SkyIrradianceBuilder(const SkyIrradianceBuilder&) = delete;
  SkyIrradianceBuilder& operator=(const SkyIrradianceBuilder&) = delete;

  // The irradiance of the sky `frame` describes (wg_sky's inputs: sky colour, ambient
  // intensity, precipitation, wind). Submits and waits, so call it outside a command
  // buffer; it dispatches only when those inputs differ from the last call's.
  const SkyIrradiance& irradianceFor(const FrameState& frame);
  const SkyIrradiance& irradiance() const { return irradiance_; }  // the last one built
  std::size_t builds() const { return builds_; }

 private:
  vk::Context& ctx_;
  std::vector<SkySample> samples_;
  vk::Buffer directions_, radiance_;
  std::unique_ptr<vk::ReflectedDescriptorSet> set_;
  vk::UniqueShaderModule module_;
  vk::UniquePipeline pipeline_;
  std::uint32_t localSize_ = 1;
  std::optional<SkyInputs> built_;
  SkyIrradiance irradiance_;
  std::size_t builds_ = 0;
};

}  // namespace wg
