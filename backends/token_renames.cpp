#include "backends/token_renames.hpp"

#include <algorithm>
#include <vector>

#include "backends/glsl_tokens.hpp"

namespace wg {

namespace {

using Tokens = std::vector<GlslToken>;

// The index of the next token that is not space, from i.
std::size_t skipSpace(const Tokens& tokens, std::size_t i) {
  while (i < tokens.size() && tokens[i].kind == GlslTokenKind::Space) ++i;
  return i;
}

bool isText(const Tokens& tokens, std::size_t i, std::string_view text) {
  return i < tokens.size() && tokens[i].text == text;
}

// "sampler2D ( a , b )" at i: the index of a and one past ')', or 0 where it is not.
std::pair<std::size_t, std::size_t> combinedSampler(const Tokens& tokens, std::size_t i) {
  std::size_t open = skipSpace(tokens, i + 1);
  if (!isText(tokens, open, "(")) return {0, 0};
  std::size_t texture = skipSpace(tokens, open + 1);
  if (texture >= tokens.size() || tokens[texture].kind != GlslTokenKind::Identifier) return {0, 0};
  std::size_t comma = skipSpace(tokens, texture + 1);
  if (!isText(tokens, comma, ",")) return {0, 0};
  std::size_t sampler = skipSpace(tokens, comma + 1);
  if (sampler >= tokens.size() || tokens[sampler].kind != GlslTokenKind::Identifier) return {0, 0};
  std::size_t close = skipSpace(tokens, sampler + 1);
  if (!isText(tokens, close, ")")) return {0, 0};
  return {texture, close + 1};
}

}  // namespace

namespace {

// With samplers to combine: token by token, looking ahead at each sampler2D.
std::string renameCombiningSamplers(std::string_view code, const TokenRenames& renames) {
  const Tokens tokens = tokenizeGlsl(code);
  std::string out;
  out.reserve(code.size() + code.size() / 8);
  bool afterDot = false;
  for (std::size_t i = 0; i < tokens.size(); ++i) {
    const GlslToken& token = tokens[i];
    if (token.kind == GlslTokenKind::Identifier) {
      if (!afterDot && token.text == "sampler2D") {
        if (auto [texture, end] = combinedSampler(tokens, i); end) {
          auto renamed = renames.bare.find(tokens[texture].text);
          out += renamed == renames.bare.end() ? std::string(tokens[texture].text) : renamed->second;
          i = end - 1;
          afterDot = false;
          continue;
        }
      }
      const auto& table = afterDot ? renames.member : renames.bare;
      auto renamed = table.find(token.text);
      out += renamed == table.end() ? token.text : std::string_view(renamed->second);
    } else {
      out += token.text;
    }
    if (token.kind != GlslTokenKind::Space && token.kind != GlslTokenKind::Comment) afterDot = token.text == ".";
  }
  return out;
}

}  // namespace

// Walks the text once and copies the runs between renamed identifiers whole: the
// surfaces' bodies are renamed at every compile.
std::string renameTokens(std::string_view code, const TokenRenames& renames) {
  if (renames.combineSamplers) return renameCombiningSamplers(code, renames);
  // The keys' first two characters: most identifiers start otherwise and are never hashed.
  std::vector<std::string_view> starts;
  for (const TokenTable* table : {&renames.bare, &renames.member})
    for (const auto& [key, value] : *table) {
      std::string_view start = std::string_view(key).substr(0, 2);
      if (std::find(starts.begin(), starts.end(), start) == starts.end()) starts.push_back(start);
    }
  auto mayBeKey = [&](std::string_view identifier) {
    for (std::string_view start : starts)
      if (identifier.starts_with(start)) return true;
    return false;
  };
  std::string out;
  out.reserve(code.size() + code.size() / 8);
  std::size_t copied = 0;
  bool afterDot = false;
  for (std::size_t at = 0; at < code.size();) {
    const GlslToken token = nextGlslToken(code, at);
    if (token.kind == GlslTokenKind::Identifier && mayBeKey(token.text)) {
      const auto& table = afterDot ? renames.member : renames.bare;
      if (auto renamed = table.find(token.text); renamed != table.end()) {
        out.append(code.substr(copied, at - copied));
        out += renamed->second;
        copied = at + token.text.size();
      }
    }
    if (token.kind != GlslTokenKind::Space && token.kind != GlslTokenKind::Comment) afterDot = token.text == ".";
    at += token.text.size();
  }
  out.append(code.substr(copied));
  return out;
}

}  // namespace wg
