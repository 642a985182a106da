// Turns a refill rate into whole depth quanta: refill per frame is far below one
// quantum (0.1 mm), so it accumulates and is applied only when a quantum is due. The
// running total lets tiles that were away in the store catch up when they return.
#pragma once
#include <cstdint>

#include <span>
#include <vector>

#include "snow/map_texels.hpp"
#include "snow/refill_schedule.hpp"

namespace wg::snow {

class DeformationRefill {
 public:
  // Adds rate * seconds of refill; returns the whole quanta now due (and counts them).
  std::uint32_t advance(double metresPerSecond, double seconds);
  std::uint64_t totalQuanta() const { return total_; }

 private:
  double pendingMetres_ = 0.0;
  std::uint64_t total_ = 0;
};

// Lowers the depth and rim of every texel of each tile by its quanta (the CPU form of
// the refill pass); returns the tiles grown by one texel, whose normals changed.
std::vector<TexelRect> refillOnCpu(const SnowWindow& window, MapTexels texels, std::span<const TileRefill> tiles);

}  // namespace wg::snow
