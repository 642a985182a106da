// The order the colour pass draws objects in: opaque and alpha-tested objects first, in
// scene order, then blended ones from the farthest object centre to the nearest, so
// each blends over everything behind it.
#pragma once
#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

#include "host/scene/mesh.hpp"

namespace wg {

struct DrawCandidate {
  bool blended = false;
  glm::vec3 centre{0.f};  // world space; only read for blended objects
};

// Indices into `objects`, each once.
std::vector<std::size_t> colourDrawOrder(const std::vector<DrawCandidate>& objects, glm::vec3 eye);

// The centre of a mesh's bounds after `model`.
glm::vec3 worldCentre(const scene::Mesh& mesh, const glm::mat4& model);

}  // namespace wg
