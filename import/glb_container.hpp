// The binary glTF container (GLB, glTF 2.0 section 4.4): a 12-byte header, a JSON chunk
// and an optional BIN chunk. The header's and these two chunks' lengths are checked
// against the bytes actually there, so a file whose lengths lie is an error here,
// before any parser trusts them. Bytes after the BIN chunk are left alone, as the
// specification asks for chunks of unknown types. A second chunk that is not BIN is
// refused: tinygltf reads only that layout.
#pragma once
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace wg::gltf {

struct GlbChunks {
  std::string_view json;
  std::span<const std::uint8_t> bin;  // empty when the file has no BIN chunk
};

// True when the bytes start with the GLB magic "glTF".
bool looksLikeGlb(std::span<const std::uint8_t> bytes);

// The version in the GLB header (2 for glTF 2.0, 1 for binary glTF 1.0); 0 when too short.
std::uint32_t glbVersion(std::span<const std::uint8_t> bytes);

// Splits a GLB file; on failure returns nullopt and says why in `error` (one line).
std::optional<GlbChunks> splitGlb(std::span<const std::uint8_t> bytes, std::string& error);

}  // namespace wg::gltf
