#include "snow/deformation_map.hpp"

#include "snow/beyond_window_stamping.hpp"
#include "snow/cpu_stamping.hpp"
#include "snow/deformation_texel.hpp"
#include "snow/map_lookup.hpp"
#include "snow/print_store_file.hpp"

namespace wg::snow {

DeformationMap::DeformationMap(const WindowSettings& settings, glm::vec2 camera)
    : window_(settings),
      heights_(window_.texelCount(), 0u),
      normals_(window_.texelCount(), 0u),
      store_(settings.printStoreBudget),
      schedule_(window_) {
  window_.setOrigin(window_.originFor(camera));
}

void DeformationMap::apply(std::span<const Stamp> stamps) {
  stampOnCpu(window_, texels(), stamps);
  schedule_.stamped(window_, stamps, refill_.totalQuanta());
  stampBeyondWindow(window_, stamps, store_, refill_.totalQuanta());
}

void DeformationMap::refill(double metresPerSecond, double seconds) {
  refill_.advance(metresPerSecond, seconds);
  auto tiles = schedule_.due(window_, refill_.totalQuanta(), window_.settings().refillTilesPerFrame);
  for (const TexelRect& rect : refillOnCpu(window_, texels(), tiles)) regenerateNormals(window_, texels(), rect);
}

Recentring DeformationMap::follow(glm::vec2 camera) {
  return recentre(window_, texels(), camera, store_, schedule_, refill_.totalQuanta());
}

void DeformationMap::savePrints(const std::filesystem::path& path) const {
  savePrintsFile(path, withWindowTiles(window_, heights_, store_, schedule_, refill_.totalQuanta()), window_,
                 refill_.totalQuanta());
}

void DeformationMap::loadPrints(const std::filesystem::path& path) {
  PrintTileStore loaded(store_.budgetBytes());
  loadPrintsFile(path, window_, refill_.totalQuanta(), loaded);  // throws before anything changes
  store_ = std::move(loaded);
  restoreAll(window_, texels(), store_, schedule_, refill_.totalQuanta());
}

float DeformationMap::heightAt(glm::vec2 world) const { return texelHeight(heightTexelAt(window_, heights_, world)); }
float DeformationMap::depthAt(glm::vec2 world) const { return texelDepth(heightTexelAt(window_, heights_, world)); }
glm::vec3 DeformationMap::normalAt(glm::vec2 world) const { return snow::normalAt(window_, normals_, world); }

}  // namespace wg::snow
