#include "host/image/image_compare.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdlib>

namespace wg::image {

namespace {

constexpr int kRgbChannels = 3;    // channels compared; alpha is ignored
constexpr int kAlphaChannel = 3;
constexpr int kByteMax = 255;

bool sameSize(const Image& a, const Image& b) {
  return a.valid() && b.valid() && a.width == b.width && a.height == b.height;
}

// The per-pixel error in bytes: max over RGB of |a - b|.
int pixelError(const std::uint8_t* a, const std::uint8_t* b) {
  int error = 0;
  for (int c = 0; c < kRgbChannels; ++c) error = std::max(error, std::abs(int(a[c]) - int(b[c])));
  return error;
}

}  // namespace

ImageDifference compareImages(const Image& a, const Image& b, double threshold) {
  ImageDifference difference;
  if (!sameSize(a, b)) {
    difference.sizeMismatch = true;
    difference.maxError = 1.0;
    difference.meanError = 1.0;
    difference.pixelsOverThreshold = std::max(a.rgba.size(), b.rgba.size()) / kImageChannels;
    return difference;
  }
  const std::size_t pixels = static_cast<std::size_t>(a.width) * static_cast<std::size_t>(a.height);
  int maxError = 0;
  std::uint64_t sum = 0;  // exact: at most 255 per pixel
  for (std::size_t i = 0; i < pixels; ++i) {
    const int error = pixelError(&a.rgba[i * kImageChannels], &b.rgba[i * kImageChannels]);
    maxError = std::max(maxError, error);
    sum += static_cast<std::uint64_t>(error);
    if (static_cast<double>(error) / kByteMax > threshold) ++difference.pixelsOverThreshold;
  }
  difference.maxError = static_cast<double>(maxError) / kByteMax;
  difference.meanError = static_cast<double>(sum) / kByteMax / static_cast<double>(pixels);
  return difference;
}

Image differenceImage(const Image& a, const Image& b) {
  const int width = std::max(a.valid() ? a.width : 0, b.valid() ? b.width : 0);
  const int height = std::max(a.valid() ? a.height : 0, b.valid() ? b.height : 0);
  if (width == 0 || height == 0) return {};
  auto covers = [](const Image& image, int x, int y) {
    return image.valid() && x < image.width && y < image.height;
  };
  Image out = Image::blank(width, height);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      std::uint8_t* dst = &out.rgba[out.texelOffset(x, y)];
      if (covers(a, x, y) && covers(b, x, y)) {
        const std::uint8_t* pa = &a.rgba[a.texelOffset(x, y)];
        const std::uint8_t* pb = &b.rgba[b.texelOffset(x, y)];
        for (int c = 0; c < kRgbChannels; ++c)
          dst[c] = static_cast<std::uint8_t>(std::min(std::abs(int(pa[c]) - int(pb[c])) * kDifferenceGain, kByteMax));
      } else {
        std::copy(kMismatchRgb, kMismatchRgb + kRgbChannels, dst);
      }
      dst[kAlphaChannel] = kByteMax;
    }
  }
  return out;
}

std::optional<Image> downsample(const Image& image, int factor) {
  if (!image.valid() || factor < 1 || image.width % factor != 0 || image.height % factor != 0)
    return std::nullopt;
  Image out = Image::blank(image.width / factor, image.height / factor);
  const std::uint64_t samples = static_cast<std::uint64_t>(factor) * static_cast<std::uint64_t>(factor);
  for (int y = 0; y < out.height; ++y) {
    for (int x = 0; x < out.width; ++x) {
      std::uint64_t sums[kImageChannels] = {};  // no overflow even for huge factors
      for (int dy = 0; dy < factor; ++dy)
        for (int dx = 0; dx < factor; ++dx) {
          const std::uint8_t* p = &image.rgba[image.texelOffset(x * factor + dx, y * factor + dy)];
          for (int c = 0; c < kImageChannels; ++c) sums[c] += p[c];
        }
      std::uint8_t* dst = &out.rgba[out.texelOffset(x, y)];
      for (int c = 0; c < kImageChannels; ++c)
        dst[c] = static_cast<std::uint8_t>((sums[c] + samples / 2) / samples);
    }
  }
  return out;
}

}  // namespace wg::image
