// PNG files for rendered images, contact sheets and reference images.
#pragma once
#include <optional>
#include <string>

#include "nodes/texture_image.hpp"

namespace wg::image {

// The widest and tallest picture writePng accepts: stb_image_write's int arguments bound
// the encodable size, and callers check what they will write against it first.
inline constexpr int kMaxPngDimension = 16384;

// `image` as the bytes of an 8-bit RGBA PNG, for callers that write it themselves.
// Returns "" or why it cannot be encoded (empty, too large).
std::string encodePng(const Image& image, std::string& bytes);

// Writes `image` as an 8-bit RGBA PNG. The bytes go to a temporary file in the same
// directory, which is then renamed over `path`: a reader (a test, an image viewer, a CI
// artifact upload) never sees a half-written file, and a failed write leaves neither a
// partial `path` nor the temporary behind. Returns "" on success, otherwise a one-line
// error naming the path.
std::string writePng(const std::string& path, const Image& image);

// Reads a PNG (any bit depth and colour type; expanded to RGBA8 as loadImageFile does).
// Files that are not PNGs are rejected even when stb_image could decode them, so a
// reference image cannot silently be a lossy JPEG. On failure returns nullopt and sets
// `error` to a one-line message naming the path.
std::optional<Image> readPng(const std::string& path, std::string& error);

}  // namespace wg::image
