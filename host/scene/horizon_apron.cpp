#include "host/scene/horizon_apron.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace wg::scene {

namespace {
constexpr int kReliefRings = 4;          // rings over which the relief fades in
constexpr float kSmoothingPerRing = 3.f;  // border vertices added to the smoothing window per ring

// The field's border vertices in order round the square (rows along z, as
// heightFieldTerrain lays them out), each once.
std::vector<std::uint32_t> borderLoop(int n) {
  std::vector<std::uint32_t> loop;
  auto idx = [n](int i, int j) { return static_cast<std::uint32_t>(j * n + i); };
  for (int i = 0; i < n - 1; ++i) loop.push_back(idx(i, 0));
  for (int j = 0; j < n - 1; ++j) loop.push_back(idx(n - 1, j));
  for (int i = n - 1; i > 0; --i) loop.push_back(idx(i, n - 1));
  for (int j = n - 1; j > 0; --j) loop.push_back(idx(0, j));
  return loop;
}

// Heights averaged over `radius` neighbours either side, round the closed loop.
std::vector<float> smoothedRound(const std::vector<float>& h, int radius) {
  const int k = static_cast<int>(h.size());
  radius = std::min(radius, (k - 1) / 2);
  std::vector<float> out(h.size());
  for (int i = 0; i < k; ++i) {
    double sum = 0.0;
    for (int d = -radius; d <= radius; ++d) sum += h[static_cast<std::size_t>(((i + d) % k + k) % k)];
    out[static_cast<std::size_t>(i)] = static_cast<float>(sum / (2 * radius + 1));
  }
  return out;
}
}  // namespace

Mesh horizonApron(const Mesh& field, int verticesPerSide, const HeightFn& relief, const HorizonApronSettings& settings) {
  const std::vector<std::uint32_t> border = borderLoop(verticesPerSide);
  const std::size_t k = border.size();
  std::vector<float> heights(k);
  for (std::size_t i = 0; i < k; ++i) heights[i] = field.positions[border[i]].y;
  const float half = std::abs(field.positions[border.front()].x);
  const float growth = std::pow(settings.reach / half, 1.f / static_cast<float>(settings.rings));

  Mesh m;
  for (std::size_t i = 0; i < k; ++i)
    addVertex(m, field.positions[border[i]], field.normals[border[i]], field.texcoords[border[i]]);
  for (int r = 1; r <= settings.rings; ++r) {
    const float scale = std::pow(growth, static_cast<float>(r));
    const float fade = std::min(1.f, static_cast<float>(r) / kReliefRings);
    const std::vector<float> smooth = smoothedRound(heights, static_cast<int>(kSmoothingPerRing * static_cast<float>(r)));
    for (std::size_t i = 0; i < k; ++i) {
      glm::vec3 edge = field.positions[border[i]];
      glm::vec2 xz = glm::vec2(edge.x, edge.z) * scale;
      glm::vec3 p(xz.x, smooth[i] + fade * relief(xz.x, xz.y), xz.y);
      addVertex(m, p, glm::vec3(0.f, 1.f, 0.f), xz / settings.uvTiling);
    }
  }
  const glm::vec3 up(0.f, 1.f, 0.f);
  for (int r = 0; r < settings.rings; ++r)
    for (std::size_t i = 0; i < k; ++i) {
      auto at = [&](int ring, std::size_t j) { return static_cast<std::uint32_t>(static_cast<std::size_t>(ring) * k + j % k); };
      addQuadFacing(m, at(r, i), at(r + 1, i), at(r + 1, i + 1), at(r, i + 1), up);
    }
  // Smooth normals beyond the border; the border keeps the field's, so the two shade alike.
  std::vector<glm::vec3> borderNormals(m.normals.begin(), m.normals.begin() + static_cast<std::ptrdiff_t>(k));
  computeNormals(m);
  std::copy(borderNormals.begin(), borderNormals.end(), m.normals.begin());
  computeTangents(m);
  return m;
}

}  // namespace wg::scene
