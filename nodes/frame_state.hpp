// The CPU mirror of the frame and weather uniform block: one member per block member
// (nodes/frame_fields.hpp lists them, in block order). The weather ops read the weather
// members; the renderer fills every member and uploads the whole block from it.
#pragma once
#include <array>
#include <cstdint>

namespace wg {

using FrameMatrix = std::array<float, 16>;  // column-major, as std140 and glm store it

struct FrameState {
  FrameMatrix model{};
  FrameMatrix viewProjection{};
  FrameMatrix normalMatrix{};
  FrameMatrix lightViewProjection{};
  std::array<float, 4> skyExposureRegion{0.f, 0.f, 0.f, 0.f};
  std::array<float, 4> terrainRegion{0.f, 0.f, 0.f, 0.f};  // xz origin, 1/size (eq. 3.11)
  // The sky's diffuse light: 9 spherical-harmonic coefficients of its irradiance / pi,
  // rgb each (w unused), as host/sky_irradiance.hpp projects them.
  std::array<std::array<float, 4>, 9> skyIrradiance{};
  std::array<float, 3> cameraPosition{0.f, 2.f, 5.f};
  float time = 0.f;  // seconds
  std::array<float, 3> sunDirection{0.f, 1.f, 0.f};  // towards the sun
  float sunIntensity = 0.f;
  std::array<float, 3> sunColor{0.f, 0.f, 0.f};
  float ambientIntensity = 0.f;
  std::array<float, 3> skyColor{0.f, 0.f, 0.f};
  float temperature = 15.f;
  std::array<float, 2> windDirection{1.f, 0.f};
  float windIntensity = 0.f;
  float precipitation = 0.f;
  float sunMelt = 0.f;  // eq. 3.5's SunIntensity: the sun's melting and drying strength, not its light
  float snowLevel = 0.f, wetnessLevel = 0.f, mossLevel = 0.f, frostLevel = 0.f, puddleLevel = 0.f;
  float exposure = 1.f;
  std::uint32_t debugView = 0;
  float terrainHeightScale = 1.f;
  float shadowMapTexel = 0.f;
};

}  // namespace wg
