// Appending the pieces of a line of shader source in place: a chain of operator+
// builds and frees a temporary string at every step, which was a tenth of the stage
// writers' time.
#pragma once
#include <charconv>
#include <cstdint>
#include <string>
#include <string_view>

namespace wg {

// A whole number as decimal text, with no temporary.
struct Decimal {
  std::uint64_t value;
};

inline void appendPiece(std::string& out, std::string_view text) { out += text; }
inline void appendPiece(std::string& out, char c) { out += c; }
inline void appendPiece(std::string& out, Decimal number) {
  char digits[24];
  out.append(digits, std::to_chars(digits, digits + sizeof digits, number.value).ptr);
}

// Appends every piece to out, in order.
template <typename... Pieces>
void appendText(std::string& out, const Pieces&... pieces) {
  (appendPiece(out, pieces), ...);
}

}  // namespace wg
