// The shading library's sky (wg_sky) in the host's own compute passes, so that what they
// draw or integrate is the sky the surfaces reflect: the library's own text, with the
// frame members it reads defined from two vec4s of the pass's push constants.
#pragma once
#include <glm/glm.hpp>

#include <string>
#include <string_view>
#include <vector>

#include "nodes/frame_state.hpp"

namespace wg {

// What wg_sky reads: the zenith colour (rgb, linear) and ambient intensity in `sky`;
// precipitation and wind intensity in x and y of `weather` (z and w are the pass's own).
struct SkyInputs {
  glm::vec4 sky{0.f};
  glm::vec4 weather{0.f};
  bool operator==(const SkyInputs&) const = default;
};
SkyInputs skyInputs(const FrameState& frame);

// The library functions named and those they call, after #defines that read the frame
// members from `<block>.sky` and `<block>.weather`.
std::string skyLibraryText(std::string_view block, const std::vector<std::string_view>& functions);

}  // namespace wg
