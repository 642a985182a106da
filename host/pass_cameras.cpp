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

TopDownView topDownView(const scene::Scene& scene, float margin) {
  glm::vec3 lo = scene.boundsMin - glm::vec3(margin), hi = scene.boundsMax + glm::vec3(margin);
  float sizeX = hi.x - lo.x, sizeZ = hi.z - lo.z;
  TopDownView v;
  v.top = hi.y;
  v.bottom = lo.y;
  glm::mat4& m = v.viewProjection;
  m = glm::mat4(0.f);
  m[0][0] = 2.f / sizeX;
  m[3][0] = -2.f * lo.x / sizeX - 1.f;
  m[2][1] = 2.f / sizeZ;
  m[3][1] = -2.f * lo.z / sizeZ - 1.f;
  m[1][2] = -1.f / (v.top - v.bottom);
  m[3][2] = v.top / (v.top - v.bottom);
  m[3][3] = 1.f;
  v.region = glm::vec4(lo.x, lo.z, 1.f / sizeX, 1.f / sizeZ);
  return v;
}

}  // namespace wg
