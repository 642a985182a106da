#include "runtime/snow/deformation_refill.hpp"

#include <cmath>

#include "runtime/snow/deformation_texel.hpp"

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

void refillOnCpu(MapTexels texels, std::uint32_t quanta) {
  if (quanta == 0) return;
  for (auto& t : texels.heights) t = refillTexel(t, quanta);
}

}  // namespace wg::snow
