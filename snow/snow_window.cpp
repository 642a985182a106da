#include "snow/snow_window.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace wg::snow {

TexelRect TexelRect::intersect(const TexelRect& other) const {
  glm::ivec2 lo = glm::max(min, other.min);
  glm::ivec2 hi = glm::min(min + size, other.min + other.size);
  return {lo, glm::max(hi - lo, glm::ivec2(0))};
}

SnowWindow::SnowWindow(const WindowSettings& settings) : settings_(settings) {
  if (settings.resolution == 0 || settings.tileTexels == 0 || settings.resolution % settings.tileTexels != 0 ||
      (settings.resolution / settings.tileTexels) % 2 != 0)
    throw std::invalid_argument("snow window: resolution must be an even number of tiles");
  if (settings.tileTexels > kMaxTileTexels)
    throw std::invalid_argument("snow window: tiles are at most 256 texels wide (16-bit positions in the store)");
  if (!(settings.texelSize > 0.f) || !std::isfinite(settings.texelSize))
    throw std::invalid_argument("snow window: texel size must be positive");
  if (settings.workPerFrame == 0 || settings.refillTilesPerFrame == 0)
    throw std::invalid_argument("snow window: a frame's work and its refilled tiles must be at least 1");
}

glm::ivec2 SnowWindow::texelAt(glm::vec2 world) const {
  return glm::ivec2(std::floor(world.x / texelSize()), std::floor(world.y / texelSize()));
}

glm::vec2 SnowWindow::texelCentre(glm::ivec2 texel) const { return (glm::vec2(texel) + 0.5f) * texelSize(); }

std::size_t SnowWindow::storageIndex(glm::ivec2 texel) const {
  int n = resolution();
  return std::size_t(floorMod(texel.y, n)) * std::size_t(n) + std::size_t(floorMod(texel.x, n));
}

glm::ivec2 SnowWindow::originFor(glm::vec2 camera) const {
  glm::ivec2 texel = texelAt(camera);
  int tile = tileTexels(), half = resolution() / tile / 2;
  return glm::ivec2(floorDiv(texel.x, tile) - half, floorDiv(texel.y, tile) - half) * tile;
}

}  // namespace wg::snow
