#include "snow/deformation_refill.hpp"

#include <cmath>

#include "snow/deformation_texel.hpp"

namespace wg::snow {

std::uint32_t DeformationRefill::advance(double metresPerSecond, double seconds) {
  if (!(metresPerSecond > 0.0) || !(seconds > 0.0) || !std::isfinite(metresPerSecond * seconds)) return 0;
  pendingMetres_ += metresPerSecond * seconds;
  double due = std::floor(pendingMetres_ / kDepthQuantum);
  if (due < 1.0) return 0;
  auto quanta = static_cast<std::uint32_t>(std::min(due, double(kMaxQuanta)));
  pendingMetres_ -= double(quanta) * kDepthQuantum;
  if (quanta == kMaxQuanta) pendingMetres_ = 0.0;  // everything is full already
  total_ += quanta;
  return quanta;
}

std::vector<TexelRect> refillOnCpu(const SnowWindow& window, MapTexels texels, std::span<const TileRefill> tiles) {
  std::vector<TexelRect> touched;
  const int n = window.tileTexels();
  for (const TileRefill& r : tiles) {
    for (int z = 0; z < n; ++z)
      for (int x = 0; x < n; ++x) {
        std::uint32_t& t = texels.heights[window.storageIndex(r.tile * n + glm::ivec2(x, z))];
        t = refillTexel(t, r.quanta);
      }
    touched.push_back(TexelRect{r.tile * n, glm::ivec2(n)}.grown(1).intersect(window.rect()));
  }
  return touched;
}

}  // namespace wg::snow
