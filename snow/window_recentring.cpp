#include "snow/window_recentring.hpp"

#include <algorithm>
#include <limits>

#include "snow/cpu_stamping.hpp"
#include "snow/deformation_texel.hpp"

namespace wg::snow {

namespace {

template <typename Visit>
void forEachTile(const TexelRect& rect, int tileTexels, Visit&& visit) {
  for (int tz = 0; tz < rect.size.y / tileTexels; ++tz)
    for (int tx = 0; tx < rect.size.x / tileTexels; ++tx) visit(rect.min / tileTexels + glm::ivec2(tx, tz));
}

// Moves a tile's texels out of the map (into the store when any is deformed) and
// leaves the slots untouched and flat for whatever enters there.
template <typename Visit>
void forEachTexelOf(const SnowWindow& window, glm::ivec2 tile, Visit&& visit) {
  int n = window.tileTexels();
  for (int z = 0; z < n; ++z)
    for (int x = 0; x < n; ++x) visit(std::size_t(z * n + x), window.storageIndex(tile * n + glm::ivec2(x, z)));
}

// A tile's texels, row-major, copied out of the window.
std::vector<std::uint32_t> tileTexels(const SnowWindow& window, std::span<const std::uint32_t> heights,
                                      glm::ivec2 tile) {
  std::vector<std::uint32_t> dense(std::size_t(window.tileTexels()) * std::size_t(window.tileTexels()));
  forEachTexelOf(window, tile, [&](std::size_t i, std::size_t slot) { dense[i] = heights[slot]; });
  return dense;
}

// Leaves a tile's slots untouched and flat for whatever enters there.
void resetTile(const SnowWindow& window, MapTexels texels, glm::ivec2 tile) {
  forEachTexelOf(window, tile, [&](std::size_t, std::size_t slot) {
    texels.heights[slot] = 0;
    texels.normals[slot] = 0;  // packNormal of straight up
  });
}

bool evictTile(const SnowWindow& window, MapTexels texels, glm::ivec2 tile, PrintTileStore& store,
               RefillSchedule& schedule, std::uint64_t refillQuanta) {
  StoredTile stored = packTile(tileTexels(window, texels.heights, tile), schedule.left(tile, refillQuanta));
  resetTile(window, texels, tile);
  if (stored.heights.empty()) return false;
  store.put(tile, std::move(stored));
  return true;
}

bool restoreTile(const SnowWindow& window, MapTexels texels, glm::ivec2 tile, PrintTileStore& store,
                 RefillSchedule& schedule, std::uint64_t refillQuanta) {
  auto stored = store.take(tile);
  if (!stored) {
    schedule.entered(tile, 0, refillQuanta);
    return false;
  }
  std::uint64_t missed = refillQuanta - stored->refillAtEviction;
  auto quanta = static_cast<std::uint32_t>(std::min<std::uint64_t>(missed, kMaxQuanta));
  int n = window.tileTexels();
  std::uint32_t deepest = 0;
  for (std::size_t i = 0; i < stored->heights.size(); ++i) {
    glm::ivec2 at(stored->positions[i] % n, stored->positions[i] / n);
    std::uint32_t texel = refillTexel(stored->heights[i], quanta);
    texels.heights[window.storageIndex(tile * n + at)] = texel;
    deepest = std::max({deepest, texel >> kDepthShift, texel & kMaxQuanta});
  }
  schedule.entered(tile, deepest, refillQuanta);
  return true;
}

}  // namespace

Recentring recentre(SnowWindow& window, MapTexels texels, glm::vec2 camera, PrintTileStore& store,
                    RefillSchedule& schedule, std::uint64_t refillQuanta) {
  Recentring out;
  glm::ivec2 target = window.originFor(camera);
  if (target == window.origin()) return out;
  TexelRect before = window.rect();
  TexelRect after{target, before.size};
  int n = window.tileTexels();
  forEachTile(before, n, [&](glm::ivec2 tile) {
    if (after.contains(tile * n)) return;
    ++out.evicted;
    out.stored += evictTile(window, texels, tile, store, schedule, refillQuanta);
  });
  window.setOrigin(target);
  forEachTile(after, n, [&](glm::ivec2 tile) {
    if (before.contains(tile * n)) return;
    if (!restoreTile(window, texels, tile, store, schedule, refillQuanta)) return;
    ++out.restored;
    out.restoredRects.push_back(TexelRect{tile * n, glm::ivec2(n)}.grown(1).intersect(window.rect()));
  });
  for (const auto& rect : out.restoredRects) regenerateNormals(window, texels, rect);
  return out;
}

PrintTileStore withWindowTiles(const SnowWindow& window, std::span<const std::uint32_t> heights,
                               const PrintTileStore& store, const RefillSchedule& schedule,
                               std::uint64_t refillQuanta) {
  PrintTileStore out = store;
  out.setBudget(std::numeric_limits<std::size_t>::max());  // a snapshot drops nothing
  forEachTile(window.rect(), window.tileTexels(), [&](glm::ivec2 tile) {
    out.put(tile, packTile(tileTexels(window, heights, tile), schedule.refilledTo(tile, refillQuanta)));
  });
  return out;
}

std::vector<TexelRect> restoreAll(const SnowWindow& window, MapTexels texels, PrintTileStore& store,
                                  RefillSchedule& schedule, std::uint64_t refillQuanta) {
  forEachTile(window.rect(), window.tileTexels(), [&](glm::ivec2 tile) {
    resetTile(window, texels, tile);
    schedule.left(tile, refillQuanta);
    restoreTile(window, texels, tile, store, schedule, refillQuanta);
  });
  regenerateNormals(window, texels, window.rect());
  return {window.rect()};
}

void storeAll(const SnowWindow& window, MapTexels texels, PrintTileStore& store, RefillSchedule& schedule,
              std::uint64_t refillQuanta) {
  forEachTile(window.rect(), window.tileTexels(),
              [&](glm::ivec2 tile) { evictTile(window, texels, tile, store, schedule, refillQuanta); });
}

}  // namespace wg::snow
