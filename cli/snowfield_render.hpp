// weathergen render --scene snowfield: the interactive snow animated in simulated time
// and drawn at its key moments into a labelled contact sheet and a frame strip.
#pragma once
#include <string>

#include "host/scene_renderer.hpp"

namespace wg {

struct SnowfieldRenderOptions {
  std::string output, framesDir, device, graphsDir;
  RenderRequest request;  // size, backend, AOV, weather, shadows
  bool validation = false, progress = false;
  unsigned samples = 4;  // the lit pass's MSAA
};

int renderSnowfield(const SnowfieldRenderOptions& options);

}  // namespace wg
