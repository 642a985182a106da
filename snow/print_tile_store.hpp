// The CPU-side sparse store of prints outside the window (the seed loses them, 5.1.2):
// tiles that left the window and tiles stamped while outside it. Only tiles with any
// deformation are kept, keyed by world tile, with the refill counter at the moment
// they were stored, so the refill they missed is applied when they come back. The
// store has a memory budget: past it, the tile stored longest ago goes first. Refill
// only grows, so that tile has also missed the most refill: its prints are the
// faintest.
#pragma once
#include <glm/glm.hpp>

#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "snow/snow_window.hpp"

namespace wg::snow {

// Only the deformed texels of a tile: a print trail covers a few percent of the tiles
// it crosses, so 6 bytes per deformed texel beat 4 bytes for every texel ~8x.
struct StoredTile {
  std::vector<std::uint16_t> positions;  // row-major index in the tile (tileTexels² <= 65536)
  std::vector<std::uint32_t> heights;    // the packed texel at each position
  std::uint64_t refillAtEviction = 0;    // DeformationRefill::totalQuanta() when stored
};

// World tiles in a fixed order (rows, then columns), for maps keyed by tile.
struct TileOrder {
  bool operator()(glm::ivec2 a, glm::ivec2 b) const { return std::pair(a.y, a.x) < std::pair(b.y, b.x); }
};

// A tile's texels, row-major, every one (0 = untouched), and back to the sparse form.
// `missedQuanta` of refill is applied on the way out.
std::vector<std::uint32_t> unpackTile(const StoredTile& stored, int tileTexels, std::uint32_t missedQuanta);
StoredTile packTile(std::span<const std::uint32_t> texels, std::uint64_t refillQuanta);

class PrintTileStore {
 public:
  explicit PrintTileStore(std::size_t budgetBytes = WindowSettings{}.printStoreBudget) : budget_(budgetBytes) {}

  // Stores (or replaces) a tile, then evicts the oldest tiles while over budget; an
  // empty tile is not kept.
  void put(glm::ivec2 tile, StoredTile stored);
  // Removes and returns the tile, if it is stored.
  std::optional<StoredTile> take(glm::ivec2 tile);
  bool holds(glm::ivec2 tile) const { return tiles_.count(tile) != 0; }
  const StoredTile* find(glm::ivec2 tile) const;
  std::size_t tileCount() const { return tiles_.size(); }
  // Payload plus the maps' per-node bookkeeping, as an estimate of resident memory.
  std::size_t memoryBytes() const { return bytes_; }
  std::size_t budgetBytes() const { return budget_; }
  void setBudget(std::size_t bytes);
  void clear();
  // Tiles dropped to stay within the budget, since construction.
  std::size_t tilesDropped() const { return dropped_; }

  // Every tile, oldest first (the order they would be evicted in).
  template <typename Visit>
  void forEachOldestFirst(Visit&& visit) const {
    for (const auto& [age, tile] : byAge_) visit(tile, tiles_.at(tile));
  }

 private:
  struct Entry : StoredTile {
    std::uint64_t age = 0;  // put order
  };
  void erase(std::map<glm::ivec2, Entry, TileOrder>::iterator it);
  void enforceBudget();

  std::map<glm::ivec2, Entry, TileOrder> tiles_;
  std::map<std::uint64_t, glm::ivec2> byAge_;
  std::uint64_t nextAge_ = 0;
  std::size_t bytes_ = 0, budget_, dropped_ = 0;
};

}  // namespace wg::snow
