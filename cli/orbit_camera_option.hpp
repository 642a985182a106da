// `render --camera orbit:AZIMUTH,ELEVATION[,DISTANCE]`: degrees, degrees, metres
// (host/scene/orbit_camera.hpp says which way each turns).
#pragma once
#include <optional>
#include <string>
#include <string_view>

#include "host/scene/orbit_camera.hpp"

namespace wg {

inline constexpr std::string_view kOrbitCameraPrefix = "orbit:";

bool isOrbitCamera(std::string_view camera);  // starts with "orbit:"
// nullopt and a one-line usage message (quoting the text) when it is malformed or out
// of range: elevation within +-89, distance above 0 and at most 500.
std::optional<scene::Orbit> parseOrbitCamera(const std::string& camera, std::string& error);

}  // namespace wg
