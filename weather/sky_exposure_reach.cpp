#include "weather/sky_exposure_reach.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "nodes/weather_model.hpp"

namespace wg {

namespace {

constexpr double kFar = 1e30;  // squared distance of a texel with no open texel in its line yet

// Squared distances along one line of n texels `spacing` metres apart, to the nearest
// texel whose cost is 0, given costs f (squared distances so far, kFar where unknown):
// the lower envelope of parabolas (Felzenszwalb and Huttenlocher 2012), linear in n.
// `stride` steps through the map, so rows and columns share it.
void squaredDistancesAlong(double* line, int n, std::ptrdiff_t stride, double spacing, std::vector<double>& f,
                           std::vector<int>& v, std::vector<double>& z) {
  f.resize(static_cast<std::size_t>(n));
  v.resize(static_cast<std::size_t>(n));
  z.resize(static_cast<std::size_t>(n) + 1);
  for (int q = 0; q < n; ++q) f[q] = line[q * stride];
  auto at = [spacing](int q) { return q * spacing; };
  auto meet = [&](int q, int p) {  // where the parabolas of q and p cross
    return ((f[q] + at(q) * at(q)) - (f[p] + at(p) * at(p))) / (2.0 * (at(q) - at(p)));
  };
  int k = 0;
  v[0] = 0;
  z[0] = -std::numeric_limits<double>::infinity();
  z[1] = std::numeric_limits<double>::infinity();
  for (int q = 1; q < n; ++q) {
    double s = meet(q, v[k]);
    while (k > 0 && s <= z[k]) s = meet(q, v[--k]);
    ++k;
    v[k] = q;
    z[k] = s;
    z[k + 1] = std::numeric_limits<double>::infinity();
  }
  k = 0;
  for (int q = 0; q < n; ++q) {
    while (z[k + 1] < at(q)) ++k;
    const double dx = at(q) - at(v[k]);
    line[q * stride] = std::min(dx * dx + f[v[k]], kFar);
  }
}

// Metres from each texel centre to the nearest open texel centre (Euclidean).
std::vector<double> distancesToOpen(const std::vector<bool>& open, int n, double texelX, double texelZ) {
  std::vector<double> d(open.size());
  for (std::size_t t = 0; t < open.size(); ++t) d[t] = open[t] ? 0.0 : kFar;
  std::vector<double> f, z;
  std::vector<int> v;
  for (int j = 0; j < n; ++j) squaredDistancesAlong(d.data() + static_cast<std::ptrdiff_t>(j) * n, n, 1, texelX, f, v, z);
  for (int i = 0; i < n; ++i) squaredDistancesAlong(d.data() + i, n, n, texelZ, f, v, z);
  for (double& x : d) x = std::sqrt(x);
  return d;
}

float smoothUnit(float t) {
  t = std::clamp(t, 0.f, 1.f);
  return t * t * (3.f - 2.f * t);
}

// The occluder height over a point that gives it exposure e (weather::skyExposure falls
// from 1 to 0 as the occluder rises), by bisection over its whole ramp.
float shelterHeightFor(float e) {
  float lo = 0.f, hi = 1.f;  // metres above the point; skyExposure is 0 by then
  for (int i = 0; i < 24; ++i) {
    const float mid = 0.5f * (lo + hi);
    (weather::skyExposure(0.f, mid) > e ? lo : hi) = mid;
  }
  return lo;
}

}  // namespace

std::vector<float> reachUnderOverhangs(const std::vector<float>& highest, const std::vector<float>& lowest,
                                       int resolution, float texelsPerMetreX, float texelsPerMetreZ,
                                       const ExposureReach& reach) {
  const std::size_t texels = static_cast<std::size_t>(std::max(resolution, 0)) * std::max(resolution, 0);
  if (resolution <= 0 || highest.size() != texels || lowest.size() != texels || !(texelsPerMetreX > 0.f) ||
      !(texelsPerMetreZ > 0.f))
    return highest;
  // Open: nothing stands clear of the texel's own surface (exposure 1 there).
  std::vector<bool> open(texels);
  for (std::size_t t = 0; t < texels; ++t) open[t] = weather::skyExposure(lowest[t], highest[t]) >= 1.f;
  const double texelX = 1.0 / texelsPerMetreX, texelZ = 1.0 / texelsPerMetreZ;
  const std::vector<double> centres = distancesToOpen(open, resolution, texelX, texelZ);
  // From the open texel's edge, not its centre.
  const float halfTexel = static_cast<float>(0.25 * (texelX + texelZ));
  std::vector<float> out = highest;
  for (std::size_t t = 0; t < texels; ++t) {
    if (open[t]) continue;
    const float d = std::max(static_cast<float>(centres[t]) - halfTexel, 0.f);
    const float r = std::min(reach.slant * (highest[t] - lowest[t]), reach.maxReach);
    if (!(d < r)) continue;
    const float exposure = 1.f - smoothUnit((d - 0.5f * r) / (0.5f * r));
    out[t] = std::min(highest[t], lowest[t] + shelterHeightFor(exposure));
  }
  return out;
}

}  // namespace wg
