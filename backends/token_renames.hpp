// Renames identifiers in shader text token by token (comments and numbers untouched):
// a surface's code is the stages' code with the frame's names swapped for the host
// contract's (frame_snowLevel -> weather_snowLevel, v_texcoord -> wg_in.texcoord).
#pragma once
#include <string>
#include <string_view>
#include <unordered_map>

namespace wg {

// Looked up by the token's view, without a copy.
struct TokenHash {
  using is_transparent = void;
  std::size_t operator()(std::string_view text) const { return std::hash<std::string_view>{}(text); }
};
using TokenTable = std::unordered_map<std::string, std::string, TokenHash, std::equal_to<>>;

struct TokenRenames {
  TokenTable bare;    // identifiers not after '.'
  TokenTable member;  // identifiers after '.'
  // GLSL ES has no separate samplers: sampler2D(texture, sampler) becomes the texture,
  // declared as a combined sampler2D.
  bool combineSamplers = false;
};

std::string renameTokens(std::string_view code, const TokenRenames& renames);

}  // namespace wg
