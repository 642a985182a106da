#include "import/glb_container.hpp"

#include <cstring>

namespace wg::gltf {

namespace {
constexpr std::uint32_t kMagic = 0x46546C67;      // "glTF"
constexpr std::uint32_t kJsonChunk = 0x4E4F534A;  // "JSON"
constexpr std::uint32_t kBinChunk = 0x004E4942;   // "BIN\0"
constexpr std::size_t kHeaderSize = 12, kChunkHeaderSize = 8;

std::uint32_t readU32(std::span<const std::uint8_t> bytes, std::size_t offset) {
  std::uint32_t v;
  std::memcpy(&v, bytes.data() + offset, 4);  // GLB is little-endian, as is every target we build for
  return v;
}
}  // namespace

bool looksLikeGlb(std::span<const std::uint8_t> bytes) { return bytes.size() >= 4 && readU32(bytes, 0) == kMagic; }

std::uint32_t glbVersion(std::span<const std::uint8_t> bytes) { return bytes.size() >= 8 ? readU32(bytes, 4) : 0; }

std::optional<GlbChunks> splitGlb(std::span<const std::uint8_t> bytes, std::string& error) {
  if (bytes.size() < kHeaderSize + kChunkHeaderSize) {
    error = "the GLB file is " + std::to_string(bytes.size()) + " bytes, shorter than its header";
    return std::nullopt;
  }
  if (std::uint32_t version = readU32(bytes, 4); version != 2) {
    error = "GLB version " + std::to_string(version) + "; only version 2 is glTF 2.0";
    return std::nullopt;
  }
  if (std::uint32_t length = readU32(bytes, 8); length != bytes.size()) {
    error = "the GLB header says the file is " + std::to_string(length) + " bytes, but it is " + std::to_string(bytes.size());
    return std::nullopt;
  }
  std::uint64_t jsonLength = readU32(bytes, 12);
  if (readU32(bytes, 16) != kJsonChunk) {
    error = "the first GLB chunk is not the JSON chunk";
    return std::nullopt;
  }
  std::uint64_t jsonEnd = kHeaderSize + kChunkHeaderSize + jsonLength;
  if (jsonLength == 0 || jsonEnd > bytes.size()) {
    error = "the JSON chunk claims " + std::to_string(jsonLength) + " bytes, but " +
            std::to_string(bytes.size() - kHeaderSize - kChunkHeaderSize) + " follow its header";
    return std::nullopt;
  }
  GlbChunks chunks;
  chunks.json = std::string_view(reinterpret_cast<const char*>(bytes.data()) + kHeaderSize + kChunkHeaderSize, jsonLength);
  if (jsonEnd == bytes.size()) return chunks;
  if (jsonEnd + kChunkHeaderSize > bytes.size()) {
    error = "the file ends inside the header of its second chunk";
    return std::nullopt;
  }
  std::uint64_t binLength = readU32(bytes, jsonEnd);
  if (readU32(bytes, jsonEnd + 4) != kBinChunk) {
    error = "the second GLB chunk is not a BIN chunk";
    return std::nullopt;
  }
  std::uint64_t binStart = jsonEnd + kChunkHeaderSize;
  if (binStart + binLength > bytes.size()) {
    error = "the BIN chunk claims " + std::to_string(binLength) + " bytes, but " + std::to_string(bytes.size() - binStart) +
            " follow its header";
    return std::nullopt;
  }
  chunks.bin = bytes.subspan(binStart, binLength);
  return chunks;
}

}  // namespace wg::gltf
