#include "runtime/snow/snow_patch_grid.hpp"

#include <cmath>
#include <cstdlib>
#include <stdexcept>

namespace wg::snow {

namespace {
glm::ivec2 patchOf(const PatchGridSettings& s, glm::vec3 p) {
  return {int(std::floor(p.x / s.patchSize)), int(std::floor(p.z / s.patchSize))};
}
}  // namespace

scene::Mesh patchGridMesh(const PatchGridSettings& s) {
  if (s.patches <= 0 || s.quadsPerPatch <= 0 || !(s.patchSize > 0.f))
    throw std::invalid_argument("snow patch grid: patches, size and resolution must be positive");
  scene::Mesh mesh;
  int side = s.patches * s.quadsPerPatch;  // quads per side of the whole grid
  float spacing = s.patchSize / float(s.quadsPerPatch), half = 0.5f * s.extent();
  for (int z = 0; z <= side; ++z)
    for (int x = 0; x <= side; ++x) {
      glm::vec3 p(float(x) * spacing - half, 0.f, float(z) * spacing - half);
      scene::addVertex(mesh, p, {0.f, 1.f, 0.f}, glm::vec2(p.x, p.z) / s.patchSize);
      // cross(up, +x) = -z, so w = -1 makes the bitangent +z.
      mesh.tangents.back() = {1.f, 0.f, 0.f, -1.f};
    }
  auto at = [&](int x, int z) { return static_cast<std::uint32_t>(z * (side + 1) + x); };
  for (int z = 0; z < side; ++z)
    for (int x = 0; x < side; ++x)
      scene::addQuadFacing(mesh, at(x, z), at(x + 1, z), at(x + 1, z + 1), at(x, z + 1), {0.f, 1.f, 0.f});
  return mesh;
}

glm::vec3 patchGridOrigin(const PatchGridSettings& s, glm::vec3 camera, float groundHeight) {
  glm::ivec2 patch = patchOf(s, camera);
  // Odd counts centre the camera's patch; even ones put it just past the centre.
  glm::vec2 centre = (glm::vec2(patch) + (s.patches % 2 ? 0.5f : 0.f)) * s.patchSize;
  return {centre.x, groundHeight, centre.y};
}

int wrappedPatches(const PatchGridSettings& s, glm::vec3 from, glm::vec3 to) {
  glm::ivec2 d = glm::abs(patchOf(s, to) - patchOf(s, from));
  int dx = std::min(d.x, s.patches), dz = std::min(d.y, s.patches);
  return dx * s.patches + dz * s.patches - dx * dz;  // columns plus rows, the corner once
}

}  // namespace wg::snow
