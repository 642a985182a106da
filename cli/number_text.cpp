#include "cli/number_text.hpp"

#include <charconv>
#include <cstdlib>
#include <string>
#include <system_error>

namespace wg {

namespace {

bool isDigit(char c) { return c >= '0' && c <= '9'; }

// Advances past one or more digits; false when there is none.
bool skipDigits(std::string_view text, std::size_t& at) {
  const std::size_t start = at;
  while (at < text.size() && isDigit(text[at])) ++at;
  return at > start;
}

// JSON's number grammar (RFC 8259, section 6).
bool isJsonNumber(std::string_view text) {
  std::size_t at = 0;
  if (at < text.size() && text[at] == '-') ++at;
  if (at < text.size() && text[at] == '0') ++at;
  else if (!skipDigits(text, at)) return false;
  if (at < text.size() && text[at] == '.' && !skipDigits(text, ++at)) return false;
  if (at < text.size() && (text[at] == 'e' || text[at] == 'E')) {
    ++at;
    if (at < text.size() && (text[at] == '+' || text[at] == '-')) ++at;
    if (!skipDigits(text, at)) return false;
  }
  return at == text.size();
}

}  // namespace

std::optional<double> parseNumberText(std::string_view text) {
  if (!isJsonNumber(text)) return std::nullopt;
  double value = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec == std::errc::result_out_of_range) {
    // strtod rounds to infinity or to zero as JSON readers do; the process keeps the
    // "C" locale, so its decimal point is '.'.
    return std::strtod(std::string(text).c_str(), nullptr);
  }
  if (ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
}

std::optional<std::uint32_t> parseCountText(std::string_view text, std::uint32_t min, std::uint32_t max) {
  if (text.empty() || text.size() > 10) return std::nullopt;  // more digits than any uint32 has
  for (char c : text)
    if (!isDigit(c)) return std::nullopt;
  if (text.size() > 1 && text.front() == '0') return std::nullopt;
  std::uint64_t value = 0;
  std::from_chars(text.data(), text.data() + text.size(), value);
  if (value < min || value > max) return std::nullopt;
  return static_cast<std::uint32_t>(value);
}

std::optional<PixelSize> parsePixelSizeText(std::string_view text, std::uint32_t maxSide) {
  const std::size_t x = text.find('x');
  if (x == std::string_view::npos) return std::nullopt;
  auto width = parseCountText(text.substr(0, x), 1, maxSide);
  auto height = parseCountText(text.substr(x + 1), 1, maxSide);
  if (!width || !height) return std::nullopt;
  return PixelSize{*width, *height};
}

}  // namespace wg
