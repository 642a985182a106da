#include "runtime/snow/snow_interactors.hpp"

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

void vehicleStamps(const Vehicle& v, double t0, double t1, const SnowCover& cover, std::vector<Stamp>& out) {
  if (!(t1 > t0)) return;
  float s0 = v.path.distanceAt(std::max(t0, 0.0)), s1 = v.path.distanceAt(t1);
  for (float side : {0.5f, -0.5f}) {
    glm::vec2 from = v.path.pointAt(s0) + leftOf(v.path.headingAt(s0)) * (side * v.track);
    glm::vec2 to = v.path.pointAt(s1) + leftOf(v.path.headingAt(s1)) * (side * v.track);
    out.push_back(capsule(from, to, 0.5f * v.wheelWidth, cover, v.sink));
  }
}

}  // namespace wg::snow
