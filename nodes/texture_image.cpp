#include "nodes/texture_image.hpp"

namespace wg {

namespace {
constexpr float kUnorm8Max = 255.f;  // largest 8-bit code, which decodes to 1.0
}

Image Image::blank(int width, int height) {
  Image image;
  image.width = width;
  image.height = height;
  image.rgba.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) *
                        kImageChannels,
                    0);
  return image;
}

bool Image::valid() const {
  return width > 0 && height > 0 &&
         rgba.size() == static_cast<std::size_t>(width) * static_cast<std::size_t>(height) *
                            kImageChannels;
}

std::array<float, 4> Image::texel(int x, int y) const {
  const std::uint8_t* p = rgba.data() + texelOffset(x, y);
  return {decodeUnorm8(p[0]), decodeUnorm8(p[1]), decodeUnorm8(p[2]), decodeUnorm8(p[3])};
}

void Image::setTexel(int x, int y, const std::array<float, 4>& color) {
  std::uint8_t* p = rgba.data() + texelOffset(x, y);
  for (int c = 0; c < kImageChannels; ++c) p[c] = encodeUnorm8(color[c]);
}

float decodeUnorm8(std::uint8_t byte) { return static_cast<float>(byte) / kUnorm8Max; }

std::uint8_t encodeUnorm8(float value) {
  // Written as comparisons so NaN falls to 0 instead of reaching the cast.
  if (!(value > 0.f)) return 0;
  if (!(value < 1.f)) return static_cast<std::uint8_t>(kUnorm8Max);
  // value*255 + 0.5 is positive, so truncation is round-half-up.
  return static_cast<std::uint8_t>(value * kUnorm8Max + 0.5f);
}

}  // namespace wg
