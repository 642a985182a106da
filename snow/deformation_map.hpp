// The CPU model of the deformation height map: the sliding window, its two texel
// planes, the print store, the refill counter and schedule. The GPU map
// (gpu_deformation_map.hpp, deformation_recorder.hpp) keeps the same state in
// device-local buffers and runs stamps, normals and refill as compute; tests hold the
// two against each other.
#pragma once
#include <filesystem>
#include <span>
#include <vector>

#include "snow/deformation_refill.hpp"
#include "snow/map_texels.hpp"
#include "snow/print_tile_store.hpp"
#include "snow/snow_stamp.hpp"
#include "snow/snow_window.hpp"
#include "snow/window_recentring.hpp"

namespace wg::snow {

class DeformationMap {
 public:
  explicit DeformationMap(const WindowSettings& settings = {}, glm::vec2 camera = glm::vec2(0.f));

  const SnowWindow& window() const { return window_; }
  const PrintTileStore& store() const { return store_; }
  MapTexels texels() { return {heights_, normals_}; }

  void apply(std::span<const Stamp> stamps);
  // Refill at `metresPerSecond` for `seconds`, in whole quanta, over at most
  // refillTilesPerFrame of the tiles that hold prints (refill_schedule.hpp).
  void refill(double metresPerSecond, double seconds);
  Recentring follow(glm::vec2 camera);

  // Every print, in the window and in the store, to a file (print_store_file.hpp), and
  // back: loading replaces every print with the file's. Throws PrintFileError.
  void savePrints(const std::filesystem::path& path) const;
  void loadPrints(const std::filesystem::path& path);

  // Texel values at a world point: 0 / flat outside the window.
  float heightAt(glm::vec2 world) const;  // metres, relative to the undisturbed surface
  float depthAt(glm::vec2 world) const;   // print depth, metres
  glm::vec3 normalAt(glm::vec2 world) const;

  std::size_t mapBytes() const { return (heights_.size() + normals_.size()) * sizeof(std::uint32_t); }

 private:
  SnowWindow window_;
  std::vector<std::uint32_t> heights_, normals_;
  PrintTileStore store_;
  DeformationRefill refill_;
  RefillSchedule schedule_;
};

}  // namespace wg::snow
