// The square of world the deformation height map covers: N x N texels of a fixed size,
// slid with the camera in whole tiles. Storage is toroidal: world texel (x, z) always
// lives at (x mod N, z mod N), so recentring moves no texel that stays in the window;
// only the tiles that leave or enter are touched (seed 2.3 moves whole
// rows and columns of terrain patches the same way).
#pragma once
#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>

namespace wg::snow {

// A rectangle of world texels, [min, min + size).
struct TexelRect {
  glm::ivec2 min{0};
  glm::ivec2 size{0};
  bool empty() const { return size.x <= 0 || size.y <= 0; }
  bool contains(glm::ivec2 t) const {
    return t.x >= min.x && t.y >= min.y && t.x < min.x + size.x && t.y < min.y + size.y;
  }
  TexelRect intersect(const TexelRect& other) const;
  TexelRect grown(int texels) const { return {min - texels, size + 2 * texels}; }
};

struct WindowSettings {
  // The default matches the shipped technique the issue names: 1024² at 4 cm, ~41 m.
  std::uint32_t resolution = 1024;
  float texelSize = 0.04f;
  // Recentring and the tile store work in tiles of this many texels (it divides
  // resolution). 32 texels = 1.28 m: fine enough that the camera stays near the centre,
  // coarse enough that the store holds few, 4 KiB tiles.
  std::uint32_t tileTexels = 32;
  // Memory the print store may use for tiles outside the window; past it the tiles
  // stored longest ago are dropped (print_tile_store.hpp). 16 MiB: twice the window's
  // height and normal planes.
  std::size_t printStoreBudget = std::size_t(16) << 20;
  // Tiles refilled per frame at most (refill_schedule.hpp): the refill of the whole map
  // is spread over frames instead of rewriting it at once. 4 tiles cost ~0.25 ms on
  // lavapipe, and a window full of prints (1024 tiles) is refilled every 4.3 s, faster
  // than heavy snowfall makes a quantum due (7.2 s).
  std::uint32_t refillTilesPerFrame = 4;
  // A frame's snow work, in shader invocations (DeformationRecorder::recordFrame):
  // stamps beyond it wait, oldest first, and refill and the normals of entered tiles
  // take what is left, so a frame where many feet land or the window moves costs
  // about what any other does. 8192 is ~0.45 ms on lavapipe, microseconds on a GPU,
  // and keeps up with 17 walkers and a vehicle in heavy snowfall.
  std::uint32_t workPerFrame = 8192;
};
inline constexpr std::uint32_t kMaxTileTexels = 256;

class SnowWindow {
 public:
  explicit SnowWindow(const WindowSettings& settings = {});

  const WindowSettings& settings() const { return settings_; }
  int resolution() const { return static_cast<int>(settings_.resolution); }
  float texelSize() const { return settings_.texelSize; }
  int tileTexels() const { return static_cast<int>(settings_.tileTexels); }
  float extent() const { return settings_.texelSize * float(settings_.resolution); }
  std::size_t texelCount() const { return std::size_t(settings_.resolution) * settings_.resolution; }

  // World texel of the window's lowest corner (always a multiple of tileTexels).
  glm::ivec2 origin() const { return origin_; }
  TexelRect rect() const { return {origin_, glm::ivec2(resolution())}; }

  // World xz (metres) -> the world texel that contains it, and back to its centre.
  glm::ivec2 texelAt(glm::vec2 world) const;
  glm::vec2 texelCentre(glm::ivec2 texel) const;
  // Toroidal storage index of a world texel (valid for any texel; meaningful inside).
  std::size_t storageIndex(glm::ivec2 texel) const;
  bool contains(glm::ivec2 texel) const { return rect().contains(texel); }

  // The tile-aligned origin that puts `camera` in the window's central tile.
  glm::ivec2 originFor(glm::vec2 camera) const;
  void setOrigin(glm::ivec2 origin) { origin_ = origin; }

 private:
  WindowSettings settings_;
  glm::ivec2 origin_{0};
};

// Floor division and modulo for negative world coordinates.
constexpr int floorDiv(int a, int b) { return a / b - ((a % b != 0) && ((a < 0) != (b < 0))); }
constexpr int floorMod(int a, int b) { return a - floorDiv(a, b) * b; }

// The world tiles a non-empty rectangle of texels reaches, first to last inclusive.
struct TileSpan {
  glm::ivec2 first{0}, last{-1};
};
constexpr TileSpan tilesReached(const TexelRect& rect, int tileTexels) {
  glm::ivec2 hi = rect.min + rect.size - 1;
  return {{floorDiv(rect.min.x, tileTexels), floorDiv(rect.min.y, tileTexels)},
          {floorDiv(hi.x, tileTexels), floorDiv(hi.y, tileTexels)}};
}

}  // namespace wg::snow
