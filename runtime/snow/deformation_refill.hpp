// Turns a refill rate into whole depth quanta: refill per frame is far below one
// quantum (0.1 mm), so it accumulates and is applied only when a quantum is due. The
// running total lets tiles that were away in the store catch up when they return.
#pragma once
#include <cstdint>

#include "runtime/snow/map_texels.hpp"

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

// Lowers every texel's depth and rim by `quanta` (the CPU form of the refill pass).
void refillOnCpu(MapTexels texels, std::uint32_t quanta);

}  // namespace wg::snow
