// A polyline in the ground plane walked at constant speed: the scripted movement of
// walkers, vehicles and the camera in the snowfield scene and the tests.
#pragma once
#include <glm/glm.hpp>

#include <vector>

namespace wg::snow {

class ScriptedPath {
 public:
  ScriptedPath() = default;
  // At least one point; speed in metres per second (>= 0).
  ScriptedPath(std::vector<glm::vec2> points, float speed);

  float length() const { return lengths_.empty() ? 0.f : lengths_.back(); }
  float speed() const { return speed_; }
  // Distance travelled at time t (seconds), clamped to the end of the path.
  float distanceAt(double seconds) const;
  glm::vec2 pointAt(float distance) const;
  glm::vec2 headingAt(float distance) const;  // unit tangent of the segment there

 private:
  std::size_t segmentAt(float distance) const;
  std::vector<glm::vec2> points_;
  std::vector<float> lengths_;  // cumulative, one per point
  float speed_ = 0.f;
};

}  // namespace wg::snow
