// The sky-exposure map from meshes, on the CPU (docs/weather-model.md, "Sky exposure"):
// per texel the height of the highest triangle above the texel's centre, as a depth
// render from above would give, then lowered under overhangs (sky_exposure_reach.hpp)
// by how far the highest stands above the lowest: the host should hand over its ground
// too, or an overhang is measured from its own underside.
// The reference host and engines (weathergen::weather) build it the same way.
#pragma once
#include <array>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

namespace wg {

// One triangle list in world space.
struct OccluderTriangles {
  std::span<const glm::vec3> positions;  // world space, y up
  std::span<const std::uint32_t> indices;
};

struct SkyExposureHeights {
  int resolution = 0;
  glm::vec4 region{0.f};  // origin x, origin z, 1 / size x, 1 / size z
  float floor = 0.f;      // the height where nothing is above
  std::vector<float> heights;
  std::vector<float> lowest;  // the lowest surface above each texel (floor where none): what an overhang stands over
};

// The whole builder over the box [lo, hi]: x and z give the map's region, lo.y its
// floor; rasterised, then lowered under overhangs.
SkyExposureHeights buildSkyExposure(std::span<const OccluderTriangles> meshes, glm::vec3 lo, glm::vec3 hi,
                                    int resolution);
// The box around every indexed vertex (both corners 0 when there is none).
std::pair<glm::vec3, glm::vec3> occluderBounds(std::span<const OccluderTriangles> meshes);

// Covers [lo, hi] in x and z; `floor` fills texels no triangle covers. A texel is
// covered when its centre lies inside the triangle's xz projection (edges included).
SkyExposureHeights rasteriseFromAbove(std::span<const OccluderTriangles> meshes, glm::vec2 lo, glm::vec2 hi,
                                      float floor, int resolution);

}  // namespace wg
