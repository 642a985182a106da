// Which tiles of the window hold prints, and how much refill each has had. Refill runs
// over those tiles only, a few per frame, round robin, each catching up on everything it
// is owed: no frame rewrites the whole map, and untouched snow is never visited. A
// tile's deepest print is tracked as an upper bound (the deepest stamp that reached it,
// less the refill since), so a tile refill has emptied drops out without a readback.
#pragma once
#include <glm/glm.hpp>

#include <cstdint>
#include <span>
#include <vector>

#include "snow/snow_stamp.hpp"
#include "snow/snow_window.hpp"

namespace wg::snow {

struct TileRefill {
  glm::ivec2 tile{0};         // world tile
  std::uint32_t quanta = 0;   // owed refill, applied to every texel of it
};

class RefillSchedule {
 public:
  explicit RefillSchedule(const SnowWindow& window);

  // Stamps pressed into the window: each tile they reach may now hold a print as deep
  // (or a rim as high) as the stamp's.
  void stamped(const SnowWindow& window, std::span<const Stamp> stamps, std::uint64_t refillQuanta);
  // A box of texels pressed up to `deepest` quanta by anything but a stamp (a mesh).
  void pressed(const SnowWindow& window, const TexelRect& box, std::uint32_t deepest, std::uint64_t refillQuanta);
  // A tile entered the window holding prints up to `deepest` quanta, all refill applied.
  void entered(glm::ivec2 tile, std::uint32_t deepest, std::uint64_t refillQuanta);
  // A tile leaves the window: the refill counter its texels are up to date with.
  std::uint64_t left(glm::ivec2 tile, std::uint64_t refillQuanta);
  // Up to `budget` tiles that hold prints and are owed refill; they count as refilled.
  std::vector<TileRefill> due(const SnowWindow& window, std::uint64_t refillQuanta, std::size_t budget);
  // The refill counter a tile of the window is up to date with.
  std::uint64_t refilledTo(glm::ivec2 tile, std::uint64_t refillQuanta) const;
  // Tiles that may hold a print.
  std::size_t printedTiles() const;
  // Whether any tile that may hold a print is owed refill.
  bool owes(std::uint64_t refillQuanta) const;
  // Whether a tile of the window may hold a print; if not, all its texels are 0.
  bool holdsPrints(glm::ivec2 tile) const { return slots_[slotOf(tile)].deepest != 0; }

 private:
  struct Slot {
    std::uint32_t deepest = 0;   // upper bound of any texel's depth or rim, in quanta
    std::uint64_t applied = 0;   // refill counter the texels are up to date with
  };
  std::size_t slotOf(glm::ivec2 tile) const;

  int tilesPerSide_;
  std::vector<Slot> slots_;
  std::size_t cursor_ = 0;  // where the next round robin starts
};

}  // namespace wg::snow
