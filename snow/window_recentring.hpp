// Slides the window to keep the camera in its central tile. Tiles that leave go to the
// print store if they hold any deformation; tiles that enter come back from it, with
// the refill they missed applied, or start untouched. Texels that stay are not moved
// or re-uploaded: toroidal addressing keeps them where they are.
#pragma once
#include <glm/glm.hpp>

#include <cstdint>
#include <span>
#include <vector>

#include "snow/map_texels.hpp"
#include "snow/print_tile_store.hpp"
#include "snow/refill_schedule.hpp"
#include "snow/snow_window.hpp"

namespace wg::snow {

struct Recentring {
  std::size_t evicted = 0, stored = 0, restored = 0;
  // Restored tiles, grown by one texel: their normals were regenerated on the CPU.
  std::vector<TexelRect> restoredRects;
  double gpuMilliseconds = 0.0;  // what redoing them took on a GPU map
  bool moved() const { return evicted != 0; }
};

// `schedule` says how much refill each leaving tile has had, and learns what entered.
Recentring recentre(SnowWindow& window, MapTexels texels, glm::vec2 camera, PrintTileStore& store,
                    RefillSchedule& schedule, std::uint64_t refillQuanta);

// Every tile of the window with any deformation goes to the store (the camera jumped
// away, or the layer is being torn down but its prints should outlive it).
void storeAll(const SnowWindow& window, MapTexels texels, PrintTileStore& store, RefillSchedule& schedule,
              std::uint64_t refillQuanta);

// The store plus every deformed tile of the window, changing neither: what a save writes.
PrintTileStore withWindowTiles(const SnowWindow& window, std::span<const std::uint32_t> heights,
                               const PrintTileStore& store, const RefillSchedule& schedule, std::uint64_t refillQuanta);
// The window starts over from the store: every tile of it is cleared, then taken back
// from the store if it is there (what loading saved prints does). Returns the rectangles
// whose normals were regenerated (the whole window).
std::vector<TexelRect> restoreAll(const SnowWindow& window, MapTexels texels, PrintTileStore& store,
                                  RefillSchedule& schedule, std::uint64_t refillQuanta);

}  // namespace wg::snow
