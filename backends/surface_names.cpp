#include "backends/surface_names.hpp"

#include "compiler/surface_interface.hpp"

namespace wg {

const TokenRenames& surfaceFrameNames() {
  static const TokenRenames kNames = [] {
    TokenRenames r;
    for (const auto& m : surfaceWeatherBlock().members) r.bare["frame_" + m.name] = m.identifier;
    r.bare["frame_cameraPosition"] = "wg_cameraPosition";
    return r;
  }();
  return kNames;
}

}  // namespace wg
