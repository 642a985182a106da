// Numbers typed on the command line, read by the grammar graphs use for theirs (JSON's):
// an optional '-', digits without a leading zero, an optional fraction and exponent.
// Nothing else is accepted: no '+', spaces, hex, "inf", "nan" or trailing text.
#pragma once
#include <cstdint>
#include <optional>
#include <string_view>

namespace wg {

// The number, or nullopt when `text` is not one. A number beyond double's range reads
// as infinite, so the caller's finiteness or range check reports it.
std::optional<double> parseNumberText(std::string_view text);

// A whole number from `min` to `max` (digits only), or nullopt; "4294967297" is out of
// range, never wrapped.
std::optional<std::uint32_t> parseCountText(std::string_view text, std::uint32_t min, std::uint32_t max);

struct PixelSize {
  std::uint32_t width = 0, height = 0;
};

// "WxH" with each side a count from 1 to `maxSide`, or nullopt.
std::optional<PixelSize> parsePixelSizeText(std::string_view text, std::uint32_t maxSide);

}  // namespace wg
