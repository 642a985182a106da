#include "snow/cpu_stamping.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "snow/deformation_texel.hpp"

namespace wg::snow {

namespace {
constexpr float kSnorm16 = 32767.f;

std::uint32_t snorm16(float v) {
  return static_cast<std::uint32_t>(static_cast<std::int32_t>(std::round(std::clamp(v, -1.f, 1.f) * kSnorm16))) & 0xFFFFu;
}
float fromSnorm16(std::uint32_t bits) {
  return std::max(float(static_cast<std::int16_t>(bits & 0xFFFFu)) / kSnorm16, -1.f);
}
}  // namespace

// Same packing as GLSL packSnorm2x16(vec2(x, z)): x in the low half.
std::uint32_t packNormal(glm::vec3 n) { return snorm16(n.x) | (snorm16(n.z) << 16); }

glm::vec3 unpackNormal(std::uint32_t packed) {
  float x = fromSnorm16(packed), z = fromSnorm16(packed >> 16);
  return {x, std::sqrt(std::max(0.f, 1.f - x * x - z * z)), z};
}

std::vector<TexelRect> stampOnCpu(const SnowWindow& window, MapTexels texels, std::span<const Stamp> stamps) {
  std::vector<TexelRect> touched;
  for (const Stamp& stamp : stamps) {
    TexelRect box = stampBounds(stamp, window);
    if (box.empty()) continue;
    for (int z = box.min.y; z < box.min.y + box.size.y; ++z)
      for (int x = box.min.x; x < box.min.x + box.size.x; ++x) {
        std::uint32_t& t = texels.heights[window.storageIndex({x, z})];
        t = std::max(t, stampTexel(stamp, window, {x, z}));
      }
    touched.push_back(box.grown(1).intersect(window.rect()));
  }
  for (const auto& rect : touched) regenerateNormals(window, texels, rect);
  return touched;
}

void regenerateNormals(const SnowWindow& window, MapTexels texels, const TexelRect& rect) {
  TexelRect inside = rect.intersect(window.rect());
  glm::ivec2 lo = window.rect().min, hi = lo + window.rect().size - 1;
  auto height = [&](int x, int z) {
    return texelHeight(texels.heights[window.storageIndex(glm::clamp(glm::ivec2(x, z), lo, hi))]);
  };
  float span = 2.f * window.texelSize();
  for (int z = inside.min.y; z < inside.min.y + inside.size.y; ++z)
    for (int x = inside.min.x; x < inside.min.x + inside.size.x; ++x) {
      float dx = (height(x + 1, z) - height(x - 1, z)) / span;
      float dz = (height(x, z + 1) - height(x, z - 1)) / span;
      texels.normals[window.storageIndex({x, z})] = packNormal(glm::normalize(glm::vec3(-dx, 1.f, -dz)));
    }
}

}  // namespace wg::snow
