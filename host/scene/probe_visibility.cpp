#include "host/scene/probe_visibility.hpp"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace wg::scene {

namespace {
// Visible when no surface is hit this close (metres) before reaching the probe.
constexpr float kProbeVisibilitySlack = 0.02f;
// Square-viewport frustum test, a little inside the edge.
constexpr float kFrustumMargin = 0.95f;
}  // namespace

bool cameraSees(const CameraPreset& c, const Probe& p, const std::vector<Mesh>& worldMeshes) {
  glm::vec3 toProbe = p.position - c.eye;
  if (glm::dot(p.normal, -toProbe) <= 0.f) return false;  // seen from behind
  glm::mat4 view = glm::lookAt(c.eye, c.target, glm::vec3(0.f, 1.f, 0.f));
  glm::vec3 v = glm::vec3(view * glm::vec4(p.position, 1.f));
  float limit = std::tan(glm::radians(0.5f * c.fovYDegrees)) * kFrustumMargin;
  if (v.z >= 0.f || std::abs(v.x) > -v.z * limit || std::abs(v.y) > -v.z * limit) return false;
  float slack = kProbeVisibilitySlack / glm::length(toProbe);
  for (const Mesh& m : worldMeshes)
    if (auto hit = raycast(m, c.eye, toProbe); hit && hit->distance < 1.f - slack) return false;
  return true;
}

void markProbeVisibility(Scene& scene, const std::vector<Mesh>& meshes) {
  for (Probe& p : scene.probes) {
    p.visibleFrom.clear();
    for (const CameraPreset& c : scene.cameras)
      if (cameraSees(c, p, meshes)) p.visibleFrom.push_back(c.name);
  }
}

std::vector<Mesh> worldMeshes(const Scene& scene) {
  std::vector<Mesh> meshes;
  for (const SceneObject& o : scene.objects) meshes.push_back(transformed(o.mesh, o.model));
  return meshes;
}

}  // namespace wg::scene
