// Stamps made outside the window go straight into the print store, so nothing the
// movers do is lost however far from the camera it happens; when the window reaches
// those tiles, recentring restores them like any tile that left. A stamp across the
// window's edge is split: the map takes the part inside, the store the rest. A stamp
// longer than 1 km (a teleport, not a move) or with non-finite coordinates is not
// stored.
#pragma once
#include <cstdint>
#include <span>

#include "snow/print_tile_store.hpp"
#include "snow/snow_stamp.hpp"
#include "snow/snow_window.hpp"

namespace wg::snow {

// Merges the parts of `stamps` outside the window into the store's tiles with max, as
// the map merges them; a stored tile first catches up on the refill it missed.
// Returns the number of tiles written (only tiles the stamp can reach).
std::size_t stampBeyondWindow(const SnowWindow& window, std::span<const Stamp> stamps, PrintTileStore& store,
                              std::uint64_t refillQuanta);

}  // namespace wg::snow
