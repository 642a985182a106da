#include "nodes/height_field.hpp"

#include <algorithm>
#include <cmath>

namespace wg {

float HeightField::sample(float u, float v) const {
  if (resolution <= 0 || heights.size() != static_cast<std::size_t>(resolution) * resolution) return 0.f;
  // Vulkan linear filtering: texel centres at (i + 0.5) / n, neighbours clamped.
  float x = u * resolution - 0.5f, y = v * resolution - 0.5f;
  float fx = std::floor(x), fy = std::floor(y);
  float ax = x - fx, ay = y - fy;
  auto at = [&](int i, int j) {
    i = std::clamp(i, 0, resolution - 1);
    j = std::clamp(j, 0, resolution - 1);
    return heights[static_cast<std::size_t>(j) * resolution + i];
  };
  int i = static_cast<int>(fx), j = static_cast<int>(fy);
  float top = at(i, j) + (at(i + 1, j) - at(i, j)) * ax;
  float bottom = at(i, j + 1) + (at(i + 1, j + 1) - at(i, j + 1)) * ax;
  return top + (bottom - top) * ay;
}

}  // namespace wg
