// Saving and loading the print store, for games that keep the world's state. A small
// little-endian binary format, documented in docs/deformable-snow.md:
//   "WGPRINTS"  u32 version (1)  u32 tileTexels  f32 texelSize  u64 tileCount
//   then per tile, oldest first: i32 x, i32 z (world tile), u32 missed refill (quanta),
//   u32 count, count x u16 positions (strictly increasing, < tileTexels²),
//   count x u32 packed texels (non-zero).
// Refill is stored relative to the moment of saving, so a loaded tile catches up on
// what it had missed then, whatever the loading map's refill counter is. Loading reads
// one tile at a time and checks every field: a truncated or hostile file is a
// PrintFileError naming the byte and the field, never a crash, and nothing is
// allocated beyond one tile of texels at a time (the store's budget bounds the rest).
#pragma once
#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <stdexcept>

#include "snow/print_tile_store.hpp"
#include "snow/snow_window.hpp"

namespace wg::snow {

struct PrintFileError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

inline constexpr std::uint32_t kPrintFileVersion = 1;

// Every tile of `store`, oldest first; `refillQuanta` is the counter the tiles'
// refillAtEviction values are relative to (DeformationRefill::totalQuanta()).
void savePrints(const PrintTileStore& store, const SnowWindow& window, std::uint64_t refillQuanta, std::ostream& out);
// Adds the file's tiles to `store` (a tile already there is replaced), their refill
// rebased onto `refillQuanta`, all or nothing: on an error `store` is unchanged.
// Returns the number of tiles read.
std::size_t loadPrints(std::istream& in, const SnowWindow& window, std::uint64_t refillQuanta, PrintTileStore& store);

void savePrintsFile(const std::filesystem::path& path, const PrintTileStore& store, const SnowWindow& window,
                    std::uint64_t refillQuanta);
std::size_t loadPrintsFile(const std::filesystem::path& path, const SnowWindow& window, std::uint64_t refillQuanta,
                           PrintTileStore& store);

}  // namespace wg::snow
