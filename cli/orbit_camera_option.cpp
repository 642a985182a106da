#include "cli/orbit_camera_option.hpp"

#include "cli/number_text.hpp"

#include <cmath>
#include <cstdlib>
#include <vector>

#include "compiler/literal.hpp"

namespace wg {

namespace {
// The comma-separated numbers of `list`; nullopt if any is not a finite number.
std::optional<std::vector<float>> finiteNumbers(const std::string& list) {
  std::vector<float> numbers;
  std::size_t start = 0;
  while (true) {
    std::size_t comma = list.find(',', start);
    std::string item = list.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    const auto value = parseNumberText(item);
    if (!value || !std::isfinite(static_cast<float>(*value))) return std::nullopt;
    numbers.push_back(static_cast<float>(*value));
    if (comma == std::string::npos) return numbers;
    start = comma + 1;
  }
}
}  // namespace

bool isOrbitCamera(std::string_view camera) { return camera.starts_with(kOrbitCameraPrefix); }

std::optional<scene::Orbit> parseOrbitCamera(const std::string& camera, std::string& error) {
  const std::string quoted = "'" + quoteUserText(camera) + "'";
  auto numbers = finiteNumbers(camera.substr(kOrbitCameraPrefix.size()));
  if (!numbers || numbers->size() < 2 || numbers->size() > 3) {
    error = "--camera " + quoted + " takes orbit:AZIMUTH,ELEVATION[,DISTANCE] (degrees, degrees, metres; e.g. orbit:30,20)";
    return std::nullopt;
  }
  scene::Orbit orbit{(*numbers)[0], (*numbers)[1], std::nullopt};
  if (std::abs(orbit.elevationDegrees) > scene::kOrbitMaxElevationDegrees) {
    error = "--camera " + quoted + ": the elevation must be within -89 to 89 degrees";
    return std::nullopt;
  }
  if (numbers->size() == 3) {
    orbit.distance = (*numbers)[2];
    if (!(*orbit.distance > 0.f) || *orbit.distance > scene::kOrbitMaxDistance) {
      error = "--camera " + quoted + ": the distance must be above 0 and at most 500 metres";
      return std::nullopt;
    }
  }
  return orbit;
}

}  // namespace wg
