// How a material's opacity reaches the image, as glTF 2.0's alphaMode: ignored, an
// alpha test against alphaCutoff, or blended over what lies behind.
#pragma once
#include <cstdint>
#include <optional>
#include <string_view>

namespace wg {

enum class AlphaMode : std::uint8_t { Opaque, Mask, Blend };

// Graph spellings: "opaque", "mask", "blend".
std::optional<AlphaMode> parseAlphaMode(std::string_view name);
std::string_view alphaModeName(AlphaMode mode);

}  // namespace wg
