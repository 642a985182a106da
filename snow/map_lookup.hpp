// Reading one texel of a deformation map at a world point, for tests, the renderer's
// CPU side and benchmarks: the same answer from the CPU model and the GPU map.
#pragma once
#include <glm/glm.hpp>

#include <span>

#include "snow/map_texels.hpp"
#include "snow/snow_window.hpp"

namespace wg::snow {

// The packed height texel at `world`; 0 (untouched) outside the window.
std::uint32_t heightTexelAt(const SnowWindow& window, std::span<const std::uint32_t> heights, glm::vec2 world);
// The unit normal there; straight up outside the window.
glm::vec3 normalAt(const SnowWindow& window, std::span<const std::uint32_t> normals, glm::vec2 world);

}  // namespace wg::snow
