#include "weather/sky_exposure_builder.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "weather/sky_exposure_reach.hpp"

namespace wg {

namespace {

struct TexelGrid {
  glm::vec2 lo, texelSize;
  int resolution;
  // The first and last texel whose centre may lie in [a, b] along one axis.
  std::pair<int, int> span(float a, float b, int axis) const {
    const int first = static_cast<int>(std::ceil((a - lo[axis]) / texelSize[axis] - 0.5f));
    const int last = static_cast<int>(std::floor((b - lo[axis]) / texelSize[axis] - 0.5f));
    return {std::max(first, 0), std::min(last, resolution - 1)};
  }
  glm::vec2 centre(int column, int row) const { return lo + (glm::vec2(column, row) + 0.5f) * texelSize; }
};

float edge(glm::vec2 a, glm::vec2 b, glm::vec2 p) { return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x); }

// Raises every texel whose centre lies in the triangle's xz projection to the triangle's
// height there, and lowers its lowest surface to it; a triangle seen edge-on from above
// covers nothing.
void coverTexels(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, const TexelGrid& grid,
                 SkyExposureHeights& map) {
  const glm::vec2 pa(a.x, a.z), pb(b.x, b.z), pc(c.x, c.z);
  const float area = edge(pa, pb, pc);
  if (!(std::abs(area) > 1e-12f)) return;
  const glm::vec2 lo = glm::min(pa, glm::min(pb, pc)), hi = glm::max(pa, glm::max(pb, pc));
  const auto [c0, c1] = grid.span(lo.x, hi.x, 0);
  const auto [r0, r1] = grid.span(lo.y, hi.y, 1);
  for (int row = r0; row <= r1; ++row)
    for (int column = c0; column <= c1; ++column) {
      const glm::vec2 p = grid.centre(column, row);
      const float wa = edge(pb, pc, p) / area, wb = edge(pc, pa, p) / area, wc = edge(pa, pb, p) / area;
      if (wa < 0.f || wb < 0.f || wc < 0.f) continue;
      const std::size_t t = std::size_t(row) * grid.resolution + column;
      const float y = wa * a.y + wb * b.y + wc * c.y;
      map.heights[t] = std::max(map.heights[t], y);
      map.lowest[t] = std::min(map.lowest[t], y);
    }
}

}  // namespace

SkyExposureHeights rasteriseFromAbove(std::span<const OccluderTriangles> meshes, glm::vec2 lo, glm::vec2 hi,
                                      float floor, int resolution) {
  SkyExposureHeights map;
  map.resolution = resolution;
  map.floor = floor;
  const glm::vec2 size = glm::max(hi - lo, glm::vec2(1e-6f));
  map.region = glm::vec4(lo.x, lo.y, 1.f / size.x, 1.f / size.y);
  map.heights.assign(std::size_t(resolution) * resolution, floor);
  map.lowest.assign(map.heights.size(), std::numeric_limits<float>::max());
  const TexelGrid grid{lo, size / float(resolution), resolution};
  for (const OccluderTriangles& mesh : meshes)
    for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3)
      coverTexels(mesh.positions[mesh.indices[i]], mesh.positions[mesh.indices[i + 1]],
                  mesh.positions[mesh.indices[i + 2]], grid, map);
  for (float& y : map.lowest)
    if (y == std::numeric_limits<float>::max()) y = floor;  // nothing covers it, as `heights`
  return map;
}

std::pair<glm::vec3, glm::vec3> occluderBounds(std::span<const OccluderTriangles> meshes) {
  glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
  for (const OccluderTriangles& mesh : meshes)
    for (std::uint32_t index : mesh.indices) {
      lo = glm::min(lo, mesh.positions[index]);
      hi = glm::max(hi, mesh.positions[index]);
    }
  if (lo.x > hi.x) return {glm::vec3(0.f), glm::vec3(0.f)};
  return {lo, hi};
}

SkyExposureHeights buildSkyExposure(std::span<const OccluderTriangles> meshes, glm::vec3 lo, glm::vec3 hi,
                                    int resolution) {
  SkyExposureHeights map = rasteriseFromAbove(meshes, {lo.x, lo.z}, {hi.x, hi.z}, lo.y, resolution);
  map.heights = reachUnderOverhangs(map.heights, map.lowest, resolution, resolution * map.region.z,
                                    resolution * map.region.w);
  return map;
}

}  // namespace wg
