// Comparing a rendered image with a reference: error statistics, a visual difference
// for debugging a failure, and box-filter downsampling for small reference images.
#pragma once
#include <cstddef>
#include <cstdint>
#include <optional>

#include "nodes/texture_image.hpp"

namespace wg::image {

// Per-pixel error is the largest of |a - b| / 255 over R, G and B (alpha is not
// compared: renderers disagree about it and it is never displayed). A size mismatch
// is reported as the worst possible difference.
struct ImageDifference {
  double maxError = 0.0;                // largest per-pixel error, in [0, 1]
  double meanError = 0.0;               // average per-pixel error, in [0, 1]
  std::size_t pixelsOverThreshold = 0;  // pixels whose error is strictly above the threshold
  bool sizeMismatch = false;            // sizes differ (or an image is invalid): errors are 1
};

ImageDifference compareImages(const Image& a, const Image& b, double threshold);

// Multiplies |a - b| per RGB channel by this, so a one-step difference is visible.
inline constexpr int kDifferenceGain = 16;
// Where only one of two differently sized images has pixels.
inline constexpr std::uint8_t kMismatchRgb[3] = {255, 0, 255};

// An opaque image of the per-channel differences times kDifferenceGain (black where the
// images agree). With different sizes it covers both; the part only one of them covers
// is magenta.
Image differenceImage(const Image& a, const Image& b);

// Averages factor x factor blocks (all four channels, rounded to nearest). nullopt if the
// image is invalid, factor < 1, or the size is not a multiple of factor (a reference
// image must not silently drop edge pixels).
std::optional<Image> downsample(const Image& image, int factor);

}  // namespace wg::image
