// The width and height a PNG declares in its IHDR chunk, read without decoding.
#pragma once
#include <cstddef>
#include <optional>

namespace wg {

struct DeclaredImageSize {
  unsigned width = 0;
  unsigned height = 0;
};

// Bytes a caller must read for pngDeclaredSize: the signature and the IHDR chunk.
inline constexpr std::size_t kPngHeaderBytes = 24;

// The size in the IHDR that follows the PNG signature, or nullopt when `bytes` do not
// start a PNG with an IHDR. stb_image refuses to report sizes it would not decode
// ("unknown image type" for 60000x60000), so limits are checked against this instead.
std::optional<DeclaredImageSize> pngDeclaredSize(const unsigned char* bytes, std::size_t size);

}  // namespace wg
