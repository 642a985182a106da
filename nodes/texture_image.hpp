// A decoded or generated texture: 8-bit RGBA texels shared by the CPU evaluator and
// the GPU upload.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace wg {

inline constexpr int kImageChannels = 4;  // always RGBA

// RGBA8, row-major, tightly packed. Row 0 covers v in [0, 1/height) and column 0 covers
// u in [0, 1/width), which is also the order Vulkan reads an uploaded image in.
//
// Texels are 8-bit so the GPU (uploaded as R8G8B8A8_UNORM) and the CPU evaluator decode
// exactly the same values. Bytes are kept as stored: no transfer function is applied on
// load or upload. A texture declared "colorSpace": "srgb" is uploaded as R8G8B8A8_SRGB
// and decoded when sampled (nodes/texture_sampling.hpp); any other is linear data.
struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba;  // width * height * kImageChannels bytes

  // A width x height image with every byte zero.
  static Image blank(int width, int height);

  bool valid() const;  // positive size and a buffer of exactly that many texels
  std::size_t texelOffset(int x, int y) const {
    return (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
            static_cast<std::size_t>(x)) * kImageChannels;
  }
  // Texel (x, y) decoded to [0,1] the way UNORM sampling does (byte / 255).
  std::array<float, 4> texel(int x, int y) const;
  // Stores `color` (clamped to [0,1]) at (x, y), rounded to the nearest byte.
  void setTexel(int x, int y, const std::array<float, 4>& color);
};

// UNORM8 conversions. Encoding rounds to nearest, so decode(encode(x)) is the closest
// representable value to x.
float decodeUnorm8(std::uint8_t byte);
std::uint8_t encodeUnorm8(float value);

}  // namespace wg
