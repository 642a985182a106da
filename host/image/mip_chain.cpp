#include "host/image/mip_chain.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace wg {

namespace {
float srgbToLinear(float c) { return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f); }
float linearToSrgb(float c) { return c <= 0.0031308f ? c * 12.92f : 1.055f * std::pow(c, 1.f / 2.4f) - 0.055f; }

Image halve(const Image& src, const std::array<float, 256>& decode, bool srgb) {
  Image dst = Image::blank(std::max(1, src.width / 2), std::max(1, src.height / 2));
  for (int y = 0; y < dst.height; ++y)
    for (int x = 0; x < dst.width; ++x) {
      const int x0 = std::min(2 * x, src.width - 1), x1 = std::min(2 * x + 1, src.width - 1);
      const int y0 = std::min(2 * y, src.height - 1), y1 = std::min(2 * y + 1, src.height - 1);
      const std::size_t taps[4] = {src.texelOffset(x0, y0), src.texelOffset(x1, y0), src.texelOffset(x0, y1),
                                   src.texelOffset(x1, y1)};
      std::array<float, 4> sum{};
      for (std::size_t t : taps)
        for (int c = 0; c < 4; ++c) sum[c] += c < 3 ? decode[src.rgba[t + c]] : src.rgba[t + c] / 255.f;
      for (int c = 0; c < 4; ++c) sum[c] *= 0.25f;
      if (srgb)
        for (int c = 0; c < 3; ++c) sum[c] = linearToSrgb(sum[c]);
      dst.setTexel(x, y, sum);
    }
  return dst;
}
}  // namespace

std::uint32_t fullMipLevelCount(int width, int height) {
  std::uint32_t levels = 1;
  for (int n = std::max(width, height); n > 1; n /= 2) ++levels;
  return levels;
}

std::vector<Image> mipLevelsBelow(const Image& base, bool srgb) {
  std::array<float, 256> decode{};  // colour channels; alpha is always linear
  for (int i = 0; i < 256; ++i) decode[i] = srgb ? srgbToLinear(i / 255.f) : i / 255.f;
  std::vector<Image> levels;
  levels.reserve(fullMipLevelCount(base.width, base.height));  // `above` stays valid
  const Image* above = &base;
  while (above->width > 1 || above->height > 1) {
    levels.push_back(halve(*above, decode, srgb));
    above = &levels.back();
  }
  return levels;
}

}  // namespace wg
