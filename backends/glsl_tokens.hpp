// GLSL source split into tokens, each keeping its exact text, so that a translation
// can copy everything it does not rewrite byte for byte.
#pragma once
#include <cstdint>
#include <string_view>
#include <vector>

namespace wg {

enum class GlslTokenKind : std::uint8_t {
  Identifier,   // [A-Za-z_][A-Za-z0-9_]*
  Placeholder,  // an op template's "{port}", "{T}" or "{@symbol}": one opaque name
  Number,       // 1, 1.0, 1e-3, 1.0f, 1u, 0x1F: never split into a number and a name
  Comment,      // "// ..." to the end of the line, or "/* ... */"
  Space,
  Punctuation,  // one character
};

struct GlslToken {
  GlslTokenKind kind;
  std::string_view text;  // a view into the tokenized source
};

std::vector<GlslToken> tokenizeGlsl(std::string_view source);
// The token that starts at `at` (< source.size()), for a caller that walks the text.
GlslToken nextGlslToken(std::string_view source, std::size_t at);

}  // namespace wg
