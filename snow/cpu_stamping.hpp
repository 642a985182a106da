// The CPU reference of the deformation pass: stamps merged with max (as the compute
// shader's atomicMax does) and normals regenerated over the touched texels only.
#pragma once
#include <glm/glm.hpp>

#include <span>
#include <vector>

#include "snow/map_texels.hpp"
#include "snow/snow_stamp.hpp"
#include "snow/snow_window.hpp"

namespace wg::snow {

// Returns the rectangles whose normals changed (each stamp's bounds grown by one
// texel, clipped to the window).
std::vector<TexelRect> stampOnCpu(const SnowWindow& window, MapTexels texels, std::span<const Stamp> stamps);

// Normals from central differences of texelHeight; neighbours outside the window are
// clamped to the edge, since the other side of the torus is another part of the world.
void regenerateNormals(const SnowWindow& window, MapTexels texels, const TexelRect& rect);

// A unit normal packed as in MapTexels::normals, and back.
std::uint32_t packNormal(glm::vec3 normal);
glm::vec3 unpackNormal(std::uint32_t packed);

}  // namespace wg::snow
