// The sky's diffuse light as nine spherical-harmonic coefficients (Ramamoorthi and
// Hanrahan 2001, "An Efficient Representation for Irradiance Environment Maps"): the
// sky's radiance at the texel centres of a cube map, projected onto the real spherical
// harmonics of bands 0-2 (eq. 10) and convolved with the clamped cosine (eq. 8-9).
// The coefficients are kept as the frame block holds them (skyIrradiance0-8): scaled so
// that sum c_i p_i(n) is the irradiance over pi at the unit normal n, with the
// polynomials p = (1, x, y, z, xy, yz, 3y^2 - 1, xz, z^2 - x^2), y up. A sky of one
// radiance L everywhere gives c_0 = L and the rest 0: the constant ambient it replaced.
#pragma once
#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "nodes/frame_state.hpp"

namespace wg {

struct SkySample {
  glm::vec3 direction;  // unit
  float solidAngle;     // steradians
};
// The texel centres of a cube map of faceSize x faceSize texels a face, with each
// texel's solid angle (together 4 pi).
std::vector<SkySample> cubeSkySamples(std::uint32_t faceSize);

struct SkyIrradiance {
  std::array<glm::vec3, 9> coefficients{};
};
// radiance[i] is the sky's linear radiance towards samples[i].direction.
SkyIrradiance projectSkyIrradiance(std::span<const SkySample> samples, std::span<const glm::vec3> radiance);
// The irradiance over pi at the unit normal n: the shading library's wg_sky_irradiance.
glm::vec3 skyIrradianceAt(const SkyIrradiance& irradiance, glm::vec3 n);
// Into the frame block's skyIrradiance0-8.
void writeSkyIrradiance(const SkyIrradiance& irradiance, FrameState& frame);

}  // namespace wg
