#include "snow/refill_schedule.hpp"

#include <algorithm>

#include "snow/deformation_texel.hpp"

namespace wg::snow {

RefillSchedule::RefillSchedule(const SnowWindow& window)
    : tilesPerSide_(window.resolution() / window.tileTexels()),
      slots_(std::size_t(tilesPerSide_) * std::size_t(tilesPerSide_)) {}

std::size_t RefillSchedule::slotOf(glm::ivec2 tile) const {
  return std::size_t(floorMod(tile.y, tilesPerSide_)) * std::size_t(tilesPerSide_) +
         std::size_t(floorMod(tile.x, tilesPerSide_));
}

void RefillSchedule::stamped(const SnowWindow& window, std::span<const Stamp> stamps, std::uint64_t refillQuanta) {
  for (const Stamp& s : stamps)
    pressed(window, stampBounds(s, window),
            std::max(toQuanta(std::max(s.depthA, s.depthB)), toQuanta(s.rimHeight)), refillQuanta);
}

void RefillSchedule::pressed(const SnowWindow& window, const TexelRect& box, std::uint32_t deepest,
                             std::uint64_t refillQuanta) {
  if (box.empty() || deepest == 0) return;
  TileSpan tiles = tilesReached(box, window.tileTexels());
  for (int tz = tiles.first.y; tz <= tiles.last.y; ++tz)
    for (int tx = tiles.first.x; tx <= tiles.last.x; ++tx) {
      Slot& slot = slots_[slotOf({tx, tz})];
      if (slot.deepest == 0) slot.applied = refillQuanta;  // untouched snow owes nothing
      slot.deepest = std::max(slot.deepest, deepest);
    }
}

void RefillSchedule::entered(glm::ivec2 tile, std::uint32_t deepest, std::uint64_t refillQuanta) {
  slots_[slotOf(tile)] = {deepest, refillQuanta};
}

std::uint64_t RefillSchedule::left(glm::ivec2 tile, std::uint64_t refillQuanta) {
  std::uint64_t applied = refilledTo(tile, refillQuanta);
  slots_[slotOf(tile)] = {0, refillQuanta};
  return applied;
}

std::vector<TileRefill> RefillSchedule::due(const SnowWindow& window, std::uint64_t refillQuanta,
                                            std::size_t budget) {
  std::vector<TileRefill> out;
  const int n = window.tileTexels();
  const glm::ivec2 originTile(floorDiv(window.origin().x, n), floorDiv(window.origin().y, n));
  const std::size_t start = cursor_;
  for (std::size_t visited = 0; visited < slots_.size() && out.size() < budget; ++visited) {
    std::size_t i = (start + visited) % slots_.size();
    Slot& slot = slots_[i];
    if (slot.deepest == 0 || slot.applied >= refillQuanta) continue;
    auto quanta = static_cast<std::uint32_t>(std::min<std::uint64_t>(refillQuanta - slot.applied, kMaxQuanta));
    slot.deepest = slot.deepest > quanta ? slot.deepest - quanta : 0;
    slot.applied = refillQuanta;
    glm::ivec2 s(int(i % std::size_t(tilesPerSide_)), int(i / std::size_t(tilesPerSide_)));
    glm::ivec2 tile(originTile.x + floorMod(s.x - originTile.x, tilesPerSide_),
                    originTile.y + floorMod(s.y - originTile.y, tilesPerSide_));
    out.push_back({tile, quanta});
    cursor_ = i + 1;
  }
  return out;
}

std::uint64_t RefillSchedule::refilledTo(glm::ivec2 tile, std::uint64_t refillQuanta) const {
  const Slot& slot = slots_[slotOf(tile)];
  return slot.deepest == 0 ? refillQuanta : slot.applied;
}

bool RefillSchedule::owes(std::uint64_t refillQuanta) const {
  return std::any_of(slots_.begin(), slots_.end(),
                     [&](const Slot& s) { return s.deepest != 0 && s.applied < refillQuanta; });
}

std::size_t RefillSchedule::printedTiles() const {
  return std::size_t(std::count_if(slots_.begin(), slots_.end(), [](const Slot& s) { return s.deepest != 0; }));
}

}  // namespace wg::snow
