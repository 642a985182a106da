#include "snow/scripted_path.hpp"

#include <algorithm>
#include <stdexcept>

namespace wg::snow {

ScriptedPath::ScriptedPath(std::vector<glm::vec2> points, float speed) : points_(std::move(points)), speed_(speed) {
  if (points_.empty()) throw std::invalid_argument("scripted path: no points");
  if (!(speed >= 0.f)) throw std::invalid_argument("scripted path: negative speed");
  float total = 0.f;
  lengths_.push_back(0.f);
  for (std::size_t i = 1; i < points_.size(); ++i) lengths_.push_back(total += glm::distance(points_[i - 1], points_[i]));
}

float ScriptedPath::distanceAt(double seconds) const {
  return std::clamp(float(seconds) * speed_, 0.f, length());
}

std::size_t ScriptedPath::segmentAt(float distance) const {
  if (points_.size() < 2) return 0;
  auto it = std::upper_bound(lengths_.begin(), lengths_.end(), distance);
  std::size_t i = it == lengths_.begin() ? 0 : std::size_t(it - lengths_.begin()) - 1;
  return std::min(i, points_.size() - 2);
}

glm::vec2 ScriptedPath::pointAt(float distance) const {
  if (points_.size() < 2) return points_.front();
  std::size_t i = segmentAt(distance);
  float span = lengths_[i + 1] - lengths_[i];
  float t = span > 0.f ? std::clamp((distance - lengths_[i]) / span, 0.f, 1.f) : 0.f;
  return glm::mix(points_[i], points_[i + 1], t);
}

glm::vec2 ScriptedPath::headingAt(float distance) const {
  if (points_.size() < 2) return {0.f, 1.f};
  std::size_t i = segmentAt(distance);
  glm::vec2 d = points_[i + 1] - points_[i];
  return glm::length(d) > 0.f ? glm::normalize(d) : glm::vec2(0.f, 1.f);
}

}  // namespace wg::snow
