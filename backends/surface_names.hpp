// How a surface names what library and op code calls frame_<member>: the weather's
// members as its WeatherBlock's (weather_<name>), the eye as wg_cameraPosition, a local
// its functions fill from their input struct. Op templates are spelled so once, when
// split; library pieces by the surface writer, once per spelling.
#pragma once
#include "backends/token_renames.hpp"

namespace wg {

const TokenRenames& surfaceFrameNames();

}  // namespace wg
