#include "host/pass_cameras.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace wg {

namespace {
constexpr float kNearPlane = 0.1f, kFarPlane = 600.f;

glm::mat4 flipY(glm::mat4 projection) {
  projection[1][1] *= -1.f;  // Vulkan's clip y points down
  return projection;
}
}  // namespace

ClipRange clipRange(const scene::Scene& scene, glm::vec3 eye) {
  glm::vec3 centre = 0.5f * (scene.boundsMin + scene.boundsMax);
  float reach = glm::distance(eye, centre) + 0.5f * glm::distance(scene.boundsMin, scene.boundsMax);
  float scale = std::max(1.f, 1.5f * reach / kFarPlane);
  return {kNearPlane * scale, kFarPlane * scale};
}

glm::mat4 cameraViewProjection(const scene::CameraPreset& camera, ClipRange clip, std::uint32_t width, std::uint32_t height) {
  glm::mat4 view = glm::lookAt(camera.eye, camera.target, glm::vec3(0.f, 1.f, 0.f));
  glm::mat4 projection =
      glm::perspective(glm::radians(camera.fovYDegrees), float(width) / float(height), clip.nearPlane, clip.farPlane);
  return flipY(projection) * view;
}

glm::mat4 sunViewProjection(const scene::Scene& scene, glm::vec3 towardsSun) {
  glm::vec3 centre = 0.5f * (scene.boundsMin + scene.boundsMax);
  float radius = 0.5f * glm::length(scene.boundsMax - scene.boundsMin);
  glm::vec3 up = std::abs(towardsSun.y) > 0.99f ? glm::vec3(0.f, 0.f, 1.f) : glm::vec3(0.f, 1.f, 0.f);
  glm::mat4 lightView = glm::lookAt(centre + towardsSun * (2.f * radius), centre, up);
  return flipY(glm::ortho(-radius, radius, -radius, radius, 0.01f, 4.f * radius)) * lightView;
}

}  // namespace wg
