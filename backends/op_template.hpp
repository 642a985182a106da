// An op's code template split once into its pieces: spans of text and the slots the
// stage writer fills ({T}, {input}, {@symbol}). Emitting a node then copies spans,
// instead of searching the template text for braces and names at every node.
#pragma once
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "backends/shader_syntax.hpp"
#include "nodes/op_definition.hpp"

namespace wg {

struct TemplatePiece {
  enum class Kind : std::uint8_t {
    Text,       // text: copied as it is (fixed symbols such as @texcoord become text too)
    Type,       // the node's value type
    Input,      // the operand at port `input`
    Channels,   // @channels: "." and the node's swizzle
    SampleFn,   // @sampleFn and @lodArg: depend on the stage
    LodArg,
    Parameter,  // @parameter: the material block read
    Texture,    // @texture and @sampler: the node's texture binding
    Sampler,
  };
  Kind kind = Kind::Text;
  std::string_view text;
  std::size_t input = 0;
};
struct OpTemplate {
  std::vector<TemplatePiece> pieces;
  std::vector<std::string_view> calls;  // the library functions it calls
};

// An op's template in one language with the frame's names as surfaces spell them
// (backends/surface_names.hpp), and its split, which views that text.
struct SpelledOpTemplate {
  SpelledOpTemplate(const OpDef& op, std::string_view languageCode);
  SpelledOpTemplate(const SpelledOpTemplate&) = delete;
  std::string code;
  OpTemplate split;
};

// The op's spelled template in the syntax's language, split once for every registered
// op; null for an op outside the registry (tests make some), which the caller spells.
const OpTemplate* registeredOpTemplate(const ShaderSyntax& syntax, const OpDef& op);
OpTemplate splitOpTemplate(const OpDef& op, std::string_view code);

}  // namespace wg
