#include "nodes/png_header.hpp"

#include <array>
#include <cstdint>
#include <cstring>

namespace wg {

namespace {
constexpr std::array<unsigned char, 8> kPngSignature = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
constexpr std::size_t kChunkTypeAt = 12, kWidthAt = 16, kHeightAt = 20;

std::uint32_t bigEndian32(const unsigned char* at) {
  return (std::uint32_t(at[0]) << 24) | (std::uint32_t(at[1]) << 16) | (std::uint32_t(at[2]) << 8) |
         std::uint32_t(at[3]);
}
}  // namespace

std::optional<DeclaredImageSize> pngDeclaredSize(const unsigned char* bytes, std::size_t size) {
  if (size < kPngHeaderBytes || std::memcmp(bytes, kPngSignature.data(), kPngSignature.size()) != 0 ||
      std::memcmp(bytes + kChunkTypeAt, "IHDR", 4) != 0)
    return std::nullopt;
  return DeclaredImageSize{bigEndian32(bytes + kWidthAt), bigEndian32(bytes + kHeightAt)};
}

}  // namespace wg
