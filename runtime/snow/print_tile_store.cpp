#include "runtime/snow/print_tile_store.hpp"

namespace wg::snow {

namespace {
// A std::map node: three pointers and a colour, padded, around the key and value.
constexpr std::size_t kNodeOverhead = 4 * sizeof(void*);
}  // namespace

void PrintTileStore::put(glm::ivec2 tile, StoredTile stored) { tiles_[tile] = std::move(stored); }

std::optional<StoredTile> PrintTileStore::take(glm::ivec2 tile) {
  auto it = tiles_.find(tile);
  if (it == tiles_.end()) return std::nullopt;
  StoredTile out = std::move(it->second);
  tiles_.erase(it);
  return out;
}

bool PrintTileStore::holds(glm::ivec2 tile) const { return tiles_.count(tile) != 0; }

std::size_t PrintTileStore::memoryBytes() const {
  std::size_t bytes = 0;
  for (const auto& [key, tile] : tiles_)
    bytes += kNodeOverhead + sizeof(key) + sizeof(tile) + tile.positions.capacity() * sizeof(std::uint16_t) +
             tile.heights.capacity() * sizeof(std::uint32_t);
  return bytes;
}

}  // namespace wg::snow
