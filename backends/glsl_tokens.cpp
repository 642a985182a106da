#include "backends/glsl_tokens.hpp"

namespace wg {

namespace {

bool isIdentifierStart(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_'; }
bool isDigit(char c) { return c >= '0' && c <= '9'; }
bool isIdentifierChar(char c) { return isIdentifierStart(c) || isDigit(c); }
bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

// Length of the run starting at `at` whose characters satisfy `keep`.
template <class Predicate>
std::size_t runLength(std::string_view s, std::size_t at, Predicate keep) {
  std::size_t end = at;
  while (end < s.size() && keep(s[end])) ++end;
  return end - at;
}

// A preprocessing number: digits, letters (suffixes, exponents, hex), dots, and a sign
// right after an exponent.
std::size_t numberLength(std::string_view s, std::size_t at) {
  std::size_t end = at;
  while (end < s.size()) {
    char c = s[end];
    bool sign = (c == '+' || c == '-') && (s[end - 1] == 'e' || s[end - 1] == 'E') &&
                !(s.size() > at + 1 && (s[at + 1] == 'x' || s[at + 1] == 'X'));
    if (!isIdentifierChar(c) && c != '.' && !sign) break;
    ++end;
  }
  return end - at;
}

// "{name}" or "{@name}" with nothing else inside; 0 when `at` opens no placeholder.
std::size_t placeholderLength(std::string_view s, std::size_t at) {
  std::size_t name = at + 1 + (at + 1 < s.size() && s[at + 1] == '@');
  if (name >= s.size() || !isIdentifierStart(s[name])) return 0;
  std::size_t close = name + runLength(s, name, isIdentifierChar);
  return close < s.size() && s[close] == '}' ? close + 1 - at : 0;
}

std::size_t commentLength(std::string_view s, std::size_t at) {
  if (s.substr(at, 2) == "//") {
    std::size_t end = s.find('\n', at);
    return (end == std::string_view::npos ? s.size() : end) - at;
  }
  if (s.substr(at, 2) == "/*") {
    std::size_t end = s.find("*/", at + 2);
    return (end == std::string_view::npos ? s.size() : end + 2) - at;
  }
  return 0;
}

}  // namespace

GlslToken nextGlslToken(std::string_view source, std::size_t at) {
  char c = source[at];
  GlslTokenKind kind = GlslTokenKind::Punctuation;
  std::size_t length = 1;
  if (isIdentifierStart(c)) {
    kind = GlslTokenKind::Identifier;
    length = runLength(source, at, isIdentifierChar);
  } else if (isDigit(c) || (c == '.' && at + 1 < source.size() && isDigit(source[at + 1]))) {
    kind = GlslTokenKind::Number;
    length = numberLength(source, at);
  } else if (isSpace(c)) {
    kind = GlslTokenKind::Space;
    length = runLength(source, at, isSpace);
  } else if (std::size_t comment = commentLength(source, at)) {
    kind = GlslTokenKind::Comment;
    length = comment;
  } else if (std::size_t placeholder = c == '{' ? placeholderLength(source, at) : 0) {
    kind = GlslTokenKind::Placeholder;
    length = placeholder;
  }
  return {kind, source.substr(at, length)};
}

std::vector<GlslToken> tokenizeGlsl(std::string_view source) {
  std::vector<GlslToken> tokens;
  for (std::size_t at = 0; at < source.size(); at += tokens.back().text.size())
    tokens.push_back(nextGlslToken(source, at));
  return tokens;
}

}  // namespace wg
