#include "host/display_image.hpp"

#include <algorithm>
#include <cmath>

namespace wg {

float linearToSrgb(float x) {
  x = std::clamp(x, 0.f, 1.f);
  // IEC 61966-2-1: linear segment below 0.0031308, gamma 2.4 above.
  return x <= 0.0031308f ? 12.92f * x : 1.055f * std::pow(x, 1.f / 2.4f) - 0.055f;
}

Image toDisplayImage(const RenderedFrame& frame) {
  Image image;
  image.width = static_cast<int>(frame.width);
  image.height = static_cast<int>(frame.height);
  image.rgba.resize(std::size_t(frame.width) * frame.height * 4);
  for (std::size_t i = 0; i < image.rgba.size(); ++i) {
    float v = (i % 4 == 3) ? 1.f : linearToSrgb(frame.rgba[i]);
    image.rgba[i] = static_cast<std::uint8_t>(std::lround(v * 255.f));
  }
  return image;
}

}  // namespace wg
