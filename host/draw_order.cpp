#include "host/draw_order.hpp"

#include <algorithm>

namespace wg {

std::vector<std::size_t> colourDrawOrder(const std::vector<DrawCandidate>& objects, glm::vec3 eye) {
  std::vector<std::size_t> order, blended;
  for (std::size_t i = 0; i < objects.size(); ++i) (objects[i].blended ? blended : order).push_back(i);
  auto distance = [&](std::size_t i) { return glm::distance(objects[i].centre, eye); };
  // Stable, so equally distant objects keep their scene order.
  std::stable_sort(blended.begin(), blended.end(), [&](std::size_t a, std::size_t b) { return distance(a) > distance(b); });
  order.insert(order.end(), blended.begin(), blended.end());
  return order;
}

glm::vec3 worldCentre(const scene::Mesh& mesh, const glm::mat4& model) {
  const scene::Bounds b = scene::bounds(mesh, model);
  return b.empty() ? glm::vec3(model[3]) : 0.5f * (b.min + b.max);
}

}  // namespace wg
