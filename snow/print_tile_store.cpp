#include "snow/print_tile_store.hpp"

#include "snow/deformation_texel.hpp"

namespace wg::snow {

namespace {
// A std::map node: three pointers and a colour, padded, around the key and value.
constexpr std::size_t kNodeOverhead = 4 * sizeof(void*);

std::size_t entryBytes(const StoredTile& tile) {
  return 2 * kNodeOverhead + sizeof(glm::ivec2) + sizeof(StoredTile) + 2 * sizeof(std::uint64_t) +
         sizeof(glm::ivec2) + tile.positions.capacity() * sizeof(std::uint16_t) +
         tile.heights.capacity() * sizeof(std::uint32_t);
}
}  // namespace

std::vector<std::uint32_t> unpackTile(const StoredTile& stored, int tileTexels, std::uint32_t missedQuanta) {
  std::vector<std::uint32_t> texels(std::size_t(tileTexels) * std::size_t(tileTexels), 0u);
  for (std::size_t i = 0; i < stored.heights.size(); ++i)
    texels[stored.positions[i]] = refillTexel(stored.heights[i], missedQuanta);
  return texels;
}

StoredTile packTile(std::span<const std::uint32_t> texels, std::uint64_t refillQuanta) {
  StoredTile stored;
  stored.refillAtEviction = refillQuanta;
  for (std::size_t i = 0; i < texels.size(); ++i) {
    if (texels[i] == 0) continue;
    stored.positions.push_back(static_cast<std::uint16_t>(i));
    stored.heights.push_back(texels[i]);
  }
  stored.positions.shrink_to_fit();
  stored.heights.shrink_to_fit();
  return stored;
}

void PrintTileStore::put(glm::ivec2 tile, StoredTile stored) {
  if (auto it = tiles_.find(tile); it != tiles_.end()) erase(it);
  if (stored.heights.empty()) return;
  Entry entry;
  static_cast<StoredTile&>(entry) = std::move(stored);
  entry.age = nextAge_++;
  bytes_ += entryBytes(entry);
  byAge_.emplace(entry.age, tile);
  tiles_.emplace(tile, std::move(entry));
  enforceBudget();
}

std::optional<StoredTile> PrintTileStore::take(glm::ivec2 tile) {
  auto it = tiles_.find(tile);
  if (it == tiles_.end()) return std::nullopt;
  StoredTile out = std::move(static_cast<StoredTile&>(it->second));
  bytes_ -= entryBytes(out);
  byAge_.erase(it->second.age);
  tiles_.erase(it);
  return out;
}

const StoredTile* PrintTileStore::find(glm::ivec2 tile) const {
  auto it = tiles_.find(tile);
  return it == tiles_.end() ? nullptr : &it->second;
}

void PrintTileStore::setBudget(std::size_t bytes) {
  budget_ = bytes;
  enforceBudget();
}

void PrintTileStore::clear() {
  tiles_.clear();
  byAge_.clear();
  bytes_ = 0;
}

void PrintTileStore::erase(std::map<glm::ivec2, Entry, TileOrder>::iterator it) {
  bytes_ -= entryBytes(it->second);
  byAge_.erase(it->second.age);
  tiles_.erase(it);
}

void PrintTileStore::enforceBudget() {
  while (bytes_ > budget_ && !byAge_.empty()) {
    erase(tiles_.find(byAge_.begin()->second));
    ++dropped_;
  }
}

}  // namespace wg::snow
