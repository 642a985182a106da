// Reading texture image files (PNG, JPEG, TGA, BMP) through stb_image.
#pragma once
#include <optional>
#include <string>

#include "nodes/texture_image.hpp"

namespace wg {

// Largest accepted width or height: the limit every Vulkan 1.x device guarantees
// for 2D images is 4096, but desktop GPUs all reach 8192 and larger textures are a
// mistake in a material graph anyway.
inline constexpr int kMaxImageFileDimension = 8192;

enum class ImageFileStatus { Ok, NotFound, Unsupported, TooLarge };

// Reads only the header. On Ok and TooLarge, width and height are the file's size (0
// otherwise). Unless Ok, `error` says why in one line ("file not found", "unsupported
// image format (supported: PNG, JPEG, TGA, BMP)", ...), without the path, so callers
// can prefix their own context.
ImageFileStatus probeImageFile(const std::string& path, int& width, int& height,
                               std::string& error);

// Decodes the whole file to RGBA8 (grey, grey+alpha and RGB are expanded; alpha is 255
// where the file has none; 16-bit PNGs are reduced to 8 bits). Row 0 is the top row of
// the file. On failure returns nullopt and sets `error` as probeImageFile does.
std::optional<Image> loadImageFile(const std::string& path, std::string& error);

}  // namespace wg
