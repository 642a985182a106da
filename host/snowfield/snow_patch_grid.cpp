#include "host/snowfield/snow_patch_grid.hpp"

#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace wg::snow {

namespace {
glm::ivec2 patchOf(const PatchGridSettings& s, glm::vec3 p) {
  return {int(std::floor(p.x / s.patchSize)), int(std::floor(p.z / s.patchSize))};
}

// How many `step`s make `length`; throws unless it is a whole number of them.
int wholeSteps(float length, float step, const char* what) {
  float n = length / step;
  if (std::abs(n - std::round(n)) > 1e-3f)
    throw std::invalid_argument(std::string("snow patch grid: ") + what + " is not a whole number of quads");
  return int(std::round(n));
}

void validate(const PatchGridSettings& s) {
  if (s.patches <= 0 || s.quadsPerPatch <= 0 || !(s.patchSize > 0.f))
    throw std::invalid_argument("snow patch grid: patches, size and resolution must be positive");
  if (!(s.fineHalfWidth >= 0.f) || s.fineHalfWidth > 0.5f * s.extent() || !(s.fineSpacing > 0.f) || !(s.followStep > 0.f))
    throw std::invalid_argument("snow patch grid: the fine square must lie inside the grid, with positive spacing and step");
  wholeSteps(s.followStep, s.spacing(), "the follow step");
  if (s.fineHalfWidth > 0.f) {
    wholeSteps(s.followStep, s.fineSpacing, "the follow step");
    wholeSteps(s.fineHalfWidth, s.spacing(), "the fine square");
    wholeSteps(s.fineHalfWidth, s.fineSpacing, "the fine square");
  }
}
}  // namespace

std::vector<float> patchGridLines(const PatchGridSettings& s) {
  validate(s);
  float half = 0.5f * s.extent();
  int coarse = wholeSteps(half - s.fineHalfWidth, s.spacing(), "the coarse ring");
  int fine = s.fineHalfWidth > 0.f ? wholeSteps(2.f * s.fineHalfWidth, s.fineSpacing, "the fine square") : 0;
  std::vector<float> lines;
  for (int i = 0; i < coarse; ++i) lines.push_back(-half + float(i) * s.spacing());
  for (int i = 0; i < fine; ++i) lines.push_back(-s.fineHalfWidth + float(i) * s.fineSpacing);
  for (int i = 0; i <= coarse; ++i) lines.push_back(s.fineHalfWidth + float(i) * s.spacing());
  return lines;
}

scene::Mesh patchGridMesh(const PatchGridSettings& s) {
  std::vector<float> lines = patchGridLines(s);
  scene::Mesh mesh;
  int side = int(lines.size()) - 1;  // quads per side of the whole grid
  for (float z : lines)
    for (float x : lines) {
      glm::vec3 p(x, 0.f, z);
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

glm::vec3 patchGridOrigin(const PatchGridSettings& s, glm::vec3 focus, float groundHeight) {
  validate(s);
  return {std::round(focus.x / s.followStep) * s.followStep, groundHeight, std::round(focus.z / s.followStep) * s.followStep};
}

int wrappedPatches(const PatchGridSettings& s, glm::vec3 from, glm::vec3 to) {
  glm::ivec2 d = glm::abs(patchOf(s, to) - patchOf(s, from));
  int dx = std::min(d.x, s.patches), dz = std::min(d.y, s.patches);
  return dx * s.patches + dz * s.patches - dx * dz;  // columns plus rows, the corner once
}

}  // namespace wg::snow
