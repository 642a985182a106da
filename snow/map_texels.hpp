// The two planes of the deformation map, in the window's toroidal order: packed depth
// and rim (deformation_texel.hpp) and the surface normal's x and z as two snorm16
// (y is recovered as sqrt(1 - x² - z²), always up). They live either in CPU vectors
// or in the mapped memory of the GPU buffers; all CPU-side code works on this view.
#pragma once
#include <cstdint>
#include <span>

namespace wg::snow {

struct MapTexels {
  std::span<std::uint32_t> heights;
  std::span<std::uint32_t> normals;
};

}  // namespace wg::snow
