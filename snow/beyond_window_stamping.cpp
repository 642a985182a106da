#include "snow/beyond_window_stamping.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

#include "snow/deformation_texel.hpp"

namespace wg::snow {

namespace {
// Whether the stamp can reach any texel of the tile: a long diagonal capsule (a mover
// that jumped far in one frame) has a bounding box of many tiles it never touches.
bool reachesTile(const Stamp& s, glm::ivec2 tile, const SnowWindow& window) {
  float size = window.texelSize() * float(window.tileTexels());
  glm::vec2 centre = (glm::vec2(tile) + 0.5f) * size, axis = s.b - s.a;
  float length2 = glm::dot(axis, axis);
  float t = length2 > 0.f ? std::clamp(glm::dot(centre - s.a, axis) / length2, 0.f, 1.f) : 0.f;
  float reach = std::max(s.radiusA, s.radiusB) + s.rimWidth + window.texelSize();
  return glm::length(centre - (s.a + t * axis)) <= reach + 0.7072f * size;  // half the tile's diagonal
}

// A stamp longer than this is a teleport, not a move, and leaves no rut in the store;
// non-finite or out-of-range coordinates (beyond what 32-bit texel indices hold) none
// at all. Either would otherwise walk a bounding box of billions of tiles.
constexpr float kLongestStoredStamp = 1000.f;
constexpr float kFarthestStoredPoint = 1e7f;  // metres: 2.5e8 texels of 4 cm, within int

bool storable(const Stamp& s) {
  for (glm::vec2 p : {s.a, s.b})
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || std::abs(p.x) > kFarthestStoredPoint ||
        std::abs(p.y) > kFarthestStoredPoint)
      return false;
  return glm::length(s.b - s.a) <= kLongestStoredStamp && std::isfinite(s.radiusA + s.radiusB + s.rimWidth) &&
         std::max(s.radiusA, s.radiusB) + s.rimWidth <= kLongestStoredStamp;
}
}  // namespace

std::size_t stampBeyondWindow(const SnowWindow& window, std::span<const Stamp> stamps, PrintTileStore& store,
                              std::uint64_t refillQuanta) {
  const int n = window.tileTexels();
  // Tiles this call writes, unpacked once however many stamps reach them.
  std::map<glm::ivec2, std::vector<std::uint32_t>, TileOrder> open;
  for (const Stamp& stamp : stamps) {
    if (!storable(stamp)) continue;
    TexelRect reach = stampReach(stamp, window);
    if (window.rect().intersect(reach).size == reach.size) continue;  // all inside: the map's
    TileSpan tiles = tilesReached(reach, n);
    for (int tz = tiles.first.y; tz <= tiles.last.y; ++tz)
      for (int tx = tiles.first.x; tx <= tiles.last.x; ++tx) {
        glm::ivec2 tile(tx, tz);
        if (window.contains(tile * n) || !reachesTile(stamp, tile, window)) continue;
        auto it = open.find(tile);
        if (it == open.end()) {
          std::vector<std::uint32_t> texels(std::size_t(n) * std::size_t(n), 0u);
          if (const StoredTile* stored = store.find(tile)) {
            auto missed = std::min<std::uint64_t>(refillQuanta - stored->refillAtEviction, kMaxQuanta);
            texels = unpackTile(*stored, n, static_cast<std::uint32_t>(missed));
          }
          it = open.emplace(tile, std::move(texels)).first;
        }
        TexelRect box = reach.intersect({tile * n, glm::ivec2(n)});
        for (int z = box.min.y; z < box.min.y + box.size.y; ++z)
          for (int x = box.min.x; x < box.min.x + box.size.x; ++x) {
            std::uint32_t& t = it->second[std::size_t((z - tile.y * n) * n + (x - tile.x * n))];
            t = std::max(t, stampTexel(stamp, window, {x, z}));
          }
      }
  }
  for (auto& [tile, texels] : open) store.put(tile, packTile(texels, refillQuanta));
  return open.size();
}

}  // namespace wg::snow
