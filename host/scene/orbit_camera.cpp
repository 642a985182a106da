#include "host/scene/orbit_camera.hpp"

#include <algorithm>
#include <cmath>

namespace wg::scene {

namespace {
constexpr float kFramingMargin = 1.08f;
constexpr glm::vec3 kUp{0.f, 1.f, 0.f};

// Unit vector from the target towards the camera.
glm::vec3 towardsCamera(float azimuthDegrees, float elevationDegrees) {
  float az = glm::radians(azimuthDegrees), el = glm::radians(elevationDegrees);
  return {std::sin(az) * std::cos(el), std::sin(el), std::cos(az) * std::cos(el)};
}
}  // namespace

float framingDistance(const std::vector<glm::vec3>& points, glm::vec3 target, float azimuthDegrees,
                      float elevationDegrees, float aspect, float fovYDegrees) {
  glm::vec3 back = towardsCamera(azimuthDegrees, elevationDegrees);
  glm::vec3 right = glm::normalize(glm::cross(-back, kUp)), up = glm::cross(right, -back);
  float tanY = std::tan(0.5f * glm::radians(fovYDegrees)), tanX = tanY * aspect;
  float distance = 0.f;
  for (glm::vec3 p : points) {
    // The point's depth towards the camera plus what its offset needs of the frustum.
    glm::vec3 offset = p - target;
    float depth = glm::dot(offset, back);
    distance = std::max({distance, depth + std::abs(glm::dot(offset, right)) / tanX,
                         depth + std::abs(glm::dot(offset, up)) / tanY});
  }
  return kFramingMargin * distance;
}

float framingDistance(const Bounds& bounds, float azimuthDegrees, float elevationDegrees, float aspect,
                      float fovYDegrees) {
  std::vector<glm::vec3> corners;
  for (int corner = 0; corner < 8; ++corner)
    corners.emplace_back((corner & 1) ? bounds.max.x : bounds.min.x, (corner & 2) ? bounds.max.y : bounds.min.y,
                         (corner & 4) ? bounds.max.z : bounds.min.z);
  return framingDistance(corners, 0.5f * (bounds.min + bounds.max), azimuthDegrees, elevationDegrees, aspect,
                         fovYDegrees);
}

CameraPreset orbitCamera(std::string name, glm::vec3 target, float azimuthDegrees, float elevationDegrees,
                         float distance, float fovYDegrees) {
  return {std::move(name), target + towardsCamera(azimuthDegrees, elevationDegrees) * distance, target, fovYDegrees};
}

CameraPreset orbitCamera(const Scene& scene, const Orbit& orbit, float aspect) {
  Bounds framed = scene.framedBounds();
  glm::vec3 centre = 0.5f * (framed.min + framed.max);
  float distance =
      orbit.distance.value_or(framingDistance(framed, orbit.azimuthDegrees, orbit.elevationDegrees, aspect));
  return orbitCamera("orbit", centre, orbit.azimuthDegrees, orbit.elevationDegrees, distance);
}

}  // namespace wg::scene
