#include "snow/snow_interactors.hpp"

#include <algorithm>
#include <cmath>

namespace wg::snow {

namespace {
glm::vec2 leftOf(glm::vec2 heading) { return {-heading.y, heading.x}; }
}  // namespace

glm::vec2 footfall(const Walker& w, int k) {
  float s = float(k) * w.stepLength;
  float side = (k % 2 == 0) ? 0.5f : -0.5f;
  return w.path.pointAt(s) + leftOf(w.path.headingAt(s)) * (side * w.footSpacing);
}

FootfallRange footfallsBetween(const Walker& w, double t0, double t1) {
  if (!(t1 > t0) || w.stepLength <= 0.f) return {};
  float s0 = w.path.distanceAt(t0), s1 = w.path.distanceAt(t1);
  if (t0 < 0.0) s0 = -1.f;  // the first footfall, at distance 0, happens at t = 0
  // Footfalls k with s0 < k * stepLength <= s1.
  return {std::max(int(std::floor(s0 / w.stepLength)) + 1, 0), int(std::floor(s1 / w.stepLength))};
}

void walkerStamps(const Walker& w, double t0, double t1, const SnowCover& cover, std::vector<Stamp>& out) {
  bool dragging = cover.depth > w.footLift;
  FootfallRange range = footfallsBetween(w, t0, t1);
  for (int k = range.first; k <= range.last; ++k) {
    float s = float(k) * w.stepLength;
    glm::vec2 at = footfall(w, k);
    out.push_back(footprint(at, w.path.headingAt(s), w.foot, cover, w.sink));
    if (dragging && k >= 2) {
      // The same foot's previous print (two footfalls back), joined at the foot's
      // width and at the depth the snow above the lift height allows.
      SnowCover furrow{cover.depth - w.footLift};
      out.push_back(capsule(footfall(w, k - 2), at, w.foot.heelRadius, furrow, w.sink));
    }
  }
}

namespace {
// The k-th rut mark's distance along the path; the path's end is the last mark.
float rutMark(const Vehicle& v, long k) { return std::min(float(k) * v.rutStep, v.path.length()); }
}  // namespace

void vehicleStamps(const Vehicle& v, double t0, double t1, const SnowCover& cover, std::vector<Stamp>& out) {
  if (!(t1 > t0) || !(v.rutStep > 0.f)) return;
  auto lastMark = [&](double t) {
    float s = v.path.distanceAt(t);
    return s >= v.path.length() ? long(std::ceil(v.path.length() / v.rutStep)) : long(std::floor(s / v.rutStep));
  };
  // Before t = 0 no mark is passed: the first frame presses the wheels in where they stand.
  long k0 = t0 < 0.0 ? -1 : lastMark(t0), k1 = lastMark(t1);
  if (k1 <= k0) return;  // no new mark: the vehicle has not moved since its last stamp
  float s0 = rutMark(v, std::max(k0, 0L)), s1 = rutMark(v, k1);
  for (float side : {0.5f, -0.5f}) {
    glm::vec2 from = v.path.pointAt(s0) + leftOf(v.path.headingAt(s0)) * (side * v.track);
    glm::vec2 to = v.path.pointAt(s1) + leftOf(v.path.headingAt(s1)) * (side * v.track);
    out.push_back(capsule(from, to, 0.5f * v.wheelWidth, cover, v.sink));
  }
}

}  // namespace wg::snow
