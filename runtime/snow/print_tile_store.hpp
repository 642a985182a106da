// The CPU-side sparse store of prints that left the window (issue 5, §3; the seed loses
// them, 5.1.2). Only tiles with any deformation are kept, keyed by world tile, with the
// refill counter at the moment they left, so the refill they missed is applied when
// they come back.
#pragma once
#include <glm/glm.hpp>

#include <cstdint>
#include <map>
#include <optional>
#include <utility>
#include <vector>

namespace wg::snow {

// Only the deformed texels of a tile: a print trail covers a few percent of the tiles
// it crosses, so 6 bytes per deformed texel beat 4 bytes for every texel ~8x.
struct StoredTile {
  std::vector<std::uint16_t> positions;  // row-major index in the tile (tileTexels² <= 65536)
  std::vector<std::uint32_t> heights;    // the packed texel at each position
  std::uint64_t refillAtEviction = 0;    // DeformationRefill::totalQuanta() then
};

class PrintTileStore {
 public:
  void put(glm::ivec2 tile, StoredTile stored);
  // Removes and returns the tile, if it is stored.
  std::optional<StoredTile> take(glm::ivec2 tile);
  bool holds(glm::ivec2 tile) const;
  std::size_t tileCount() const { return tiles_.size(); }
  // Payload plus the map's per-node bookkeeping, as an estimate of resident memory.
  std::size_t memoryBytes() const;

 private:
  struct Less {
    bool operator()(glm::ivec2 a, glm::ivec2 b) const { return std::pair(a.y, a.x) < std::pair(b.y, b.x); }
  };
  std::map<glm::ivec2, StoredTile, Less> tiles_;
};

}  // namespace wg::snow
