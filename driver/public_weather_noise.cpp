// weathergen::weatherNoiseTexture: the texels of the weather's shared noise texture
// (nodes/weather_noise.hpp), copied into the API's plain struct.
#include <weathergen/weathergen.hpp>

#include <exception>

#include "nodes/weather_noise.hpp"

namespace weathergen {

NoiseTexture weatherNoiseTexture() noexcept {
  try {
    const wg::Image& image = wg::weather::noiseImage();
    return {image.width, image.height, image.rgba};
  } catch (const std::exception&) {
    return {};
  }
}

}  // namespace weathergen
