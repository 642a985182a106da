// The sRGB transfer function (IEC 61966-2-1), as Vulkan's *_SRGB formats apply it when
// a texel is read: colour channels are decoded to linear before filtering.
#pragma once
#include <cstdint>

namespace wg {

// Linear value of an sRGB-encoded value in [0, 1].
float srgbToLinear(float encoded);
// Linear value of an 8-bit sRGB code, exactly srgbToLinear(byte / 255) (a table).
float decodeSrgb8(std::uint8_t byte);

}  // namespace wg
