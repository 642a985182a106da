// A float height map sampled like a Vulkan R32_SFLOAT texture with a linear,
// clamp-to-edge sampler: the CPU side of the shared terrain height map (eq. 3.11-3.12).
#pragma once
#include <vector>

namespace wg {

struct HeightField {
  int resolution = 0;          // square
  std::vector<float> heights;  // row-major; row 0 is v in [0, 1/resolution)
  float sample(float u, float v) const;  // 0 when empty
};

}  // namespace wg
