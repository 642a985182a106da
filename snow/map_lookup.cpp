#include "snow/map_lookup.hpp"

#include "snow/cpu_stamping.hpp"

namespace wg::snow {

std::uint32_t heightTexelAt(const SnowWindow& window, std::span<const std::uint32_t> heights, glm::vec2 world) {
  glm::ivec2 t = window.texelAt(world);
  return window.contains(t) ? heights[window.storageIndex(t)] : 0u;
}

glm::vec3 normalAt(const SnowWindow& window, std::span<const std::uint32_t> normals, glm::vec2 world) {
  glm::ivec2 t = window.texelAt(world);
  return window.contains(t) ? unpackNormal(normals[window.storageIndex(t)]) : glm::vec3(0.f, 1.f, 0.f);
}

}  // namespace wg::snow
