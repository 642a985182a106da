#include "nodes/srgb_transfer.hpp"

#include <array>
#include <cmath>

namespace wg {

namespace {
// IEC 61966-2-1: a linear toe below the threshold, a 2.4 power curve above it.
constexpr double kThreshold = 0.04045;
constexpr double kToeSlope = 12.92;
constexpr double kOffset = 0.055;
constexpr double kExponent = 2.4;

double decode(double c) { return c <= kThreshold ? c / kToeSlope : std::pow((c + kOffset) / (1.0 + kOffset), kExponent); }
}  // namespace

float srgbToLinear(float encoded) { return static_cast<float>(decode(encoded)); }

float decodeSrgb8(std::uint8_t byte) {
  // Computed in double and rounded once, like the tables GPU drivers use.
  static const std::array<float, 256> kTable = [] {
    std::array<float, 256> table{};
    for (int i = 0; i < 256; ++i) table[static_cast<std::size_t>(i)] = static_cast<float>(decode(i / 255.0));
    return table;
  }();
  return kTable[byte];
}

}  // namespace wg
