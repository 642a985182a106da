#include "weather/sky_exposure_reach.hpp"

#include <algorithm>
#include <cmath>

namespace wg {

namespace {

constexpr float kReachStep = 0.5f;  // metres between the eroded maps a texel picks from

// The minimum over [i - r, i + r] (clamped) for every i of a line: van Herk / Gil-Werman,
// prefix and suffix minima in blocks of 2r + 1, so the cost does not grow with r.
void slidingMin(std::vector<float>& line, int r, std::vector<float>& prefix, std::vector<float>& suffix) {
  const int n = static_cast<int>(line.size()), w = 2 * r + 1;
  if (r <= 0 || n == 0) return;
  prefix.resize(line.size());
  suffix.resize(line.size());
  for (int i = 0; i < n; ++i) prefix[i] = i % w == 0 ? line[i] : std::min(prefix[i - 1], line[i]);
  for (int i = n - 1; i >= 0; --i) suffix[i] = (i % w == w - 1 || i == n - 1) ? line[i] : std::min(suffix[i + 1], line[i]);
  for (int i = 0; i < n; ++i) line[i] = std::min(suffix[std::max(i - r, 0)], prefix[std::min(i + r, n - 1)]);
}

// The same down the columns of a row-major n x n map, all columns at once, so every
// pass reads whole rows.
void slidingMinColumns(std::vector<float>& map, int n, int r, std::vector<float>& prefix, std::vector<float>& suffix) {
  const int w = 2 * r + 1;
  if (r <= 0 || n == 0) return;
  prefix.resize(map.size());
  suffix.resize(map.size());
  auto row = [n](std::vector<float>& m, int j) { return m.begin() + static_cast<std::ptrdiff_t>(j) * n; };
  for (int j = 0; j < n; ++j) {
    if (j % w == 0) std::copy_n(row(map, j), n, row(prefix, j));
    else std::transform(row(map, j), row(map, j) + n, row(prefix, j - 1), row(prefix, j), [](float a, float b) { return std::min(a, b); });
  }
  for (int j = n - 1; j >= 0; --j) {
    if (j % w == w - 1 || j == n - 1) std::copy_n(row(map, j), n, row(suffix, j));
    else std::transform(row(map, j), row(map, j) + n, row(suffix, j + 1), row(suffix, j), [](float a, float b) { return std::min(a, b); });
  }
  for (int j = 0; j < n; ++j)
    std::transform(row(suffix, std::max(j - r, 0)), row(suffix, std::max(j - r, 0)) + n, row(prefix, std::min(j + r, n - 1)),
                   row(map, j), [](float a, float b) { return std::min(a, b); });
}

// The lowest height within rx texels along x and rz along z of each texel.
std::vector<float> minFilter(const std::vector<float>& heights, int n, int rx, int rz) {
  std::vector<float> out = heights, line(static_cast<std::size_t>(n)), prefix, suffix;
  for (int j = 0; j < n; ++j) {
    std::copy_n(out.begin() + static_cast<std::ptrdiff_t>(j) * n, n, line.begin());
    slidingMin(line, rx, prefix, suffix);
    std::copy(line.begin(), line.end(), out.begin() + static_cast<std::ptrdiff_t>(j) * n);
  }
  slidingMinColumns(out, n, rz, prefix, suffix);
  return out;
}

}  // namespace

std::vector<float> reachUnderOverhangs(const std::vector<float>& heights, int resolution, float texelsPerMetreX,
                                       float texelsPerMetreZ, const ExposureReach& reach) {
  const int steps = static_cast<int>(std::floor(reach.maxReach / kReachStep));
  if (resolution <= 0 || steps <= 0 || heights.size() != static_cast<std::size_t>(resolution) * resolution) return heights;
  auto eroded = [&](float metres) {
    return minFilter(heights, resolution, static_cast<int>(metres * texelsPerMetreX), static_cast<int>(metres * texelsPerMetreZ));
  };
  // eroded[k]: the lowest height within k quarter metres; the last is the ground estimate.
  std::vector<std::vector<float>> levels;
  for (int k = 1; k <= steps; ++k) levels.push_back(eroded(static_cast<float>(k) * kReachStep));
  const std::vector<float>& ground = levels.back();
  std::vector<float> out = heights;
  for (std::size_t t = 0; t < out.size(); ++t) {
    int k = static_cast<int>(std::floor(reach.slant * (heights[t] - ground[t]) / kReachStep));
    if (k > 0) out[t] = levels[static_cast<std::size_t>(std::min(k, steps) - 1)][t];
  }
  return out;
}

}  // namespace wg
