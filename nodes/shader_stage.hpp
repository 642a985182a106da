// The shader vocabulary every layer shares: which stage, which target language.
#pragma once
#include <cstdint>
#include <string_view>

namespace wg {

enum class ShaderStage : std::uint8_t { Vertex, Fragment };

enum class ShaderLanguage : std::uint8_t { Glsl, Hlsl };
inline std::string_view languageName(ShaderLanguage language) {  // "glsl" / "hlsl"
  return language == ShaderLanguage::Glsl ? "glsl" : "hlsl";
}

}  // namespace wg
