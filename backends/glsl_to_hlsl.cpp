#include "backends/glsl_to_hlsl.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>

#include "backends/glsl_tokens.hpp"

namespace wg {

namespace {

using Rename = std::pair<std::string_view, std::string_view>;

// Identifiers HLSL spells differently, meaning for meaning.
constexpr std::array kTokenMap = {
    Rename{"vec2", "float2"},      Rename{"vec3", "float3"},      Rename{"vec4", "float4"},
    Rename{"ivec2", "int2"},       Rename{"ivec3", "int3"},       Rename{"ivec4", "int4"},
    Rename{"uvec2", "uint2"},      Rename{"uvec3", "uint3"},      Rename{"uvec4", "uint4"},
    Rename{"bvec2", "bool2"},      Rename{"bvec3", "bool3"},      Rename{"bvec4", "bool4"},
    Rename{"mat2", "float2x2"},    Rename{"mat3", "float3x3"},    Rename{"mat4", "float4x4"},
    Rename{"mix", "lerp"},         Rename{"fract", "frac"},       Rename{"inversesqrt", "rsqrt"},
    Rename{"dFdx", "ddx"},         Rename{"dFdy", "ddy"},         Rename{"dFdxFine", "ddx_fine"},
    Rename{"dFdyFine", "ddy_fine"}, Rename{"dFdxCoarse", "ddx_coarse"}, Rename{"dFdyCoarse", "ddy_coarse"},
    Rename{"floatBitsToUint", "asuint"}, Rename{"floatBitsToInt", "asint"},
    Rename{"uintBitsToFloat", "asfloat"}, Rename{"intBitsToFloat", "asfloat"},
    Rename{"mod", "wg_glsl_mod"},  // HLSL's fmod takes the sign of x: see hlslPrelude()
};

// GLSL's component-wise comparison functions are HLSL's operators.
constexpr std::array kComparisons = {
    Rename{"lessThan", "<"},     Rename{"lessThanEqual", "<="}, Rename{"greaterThan", ">"},
    Rename{"greaterThanEqual", ">="}, Rename{"equal", "=="},    Rename{"notEqual", "!="},
};

// Sampling calls that become a method of the texture: texture(sampler2D(t, s), uv) is
// t.Sample(s, uv). An op template names the function through its {@sampleFn} symbol,
// which the HLSL syntax resolves to the method.
constexpr std::array kSamplingMethods = {
    Rename{"texture", "Sample"}, Rename{"textureLod", "SampleLevel"}, Rename{"textureGather", "Gather"},
    Rename{"{@sampleFn}", "{@sampleFn}"},
};

template <std::size_t N>
const std::string_view* lookup(const std::array<Rename, N>& table, std::string_view key) {
  auto it = std::find_if(table.begin(), table.end(), [&](const Rename& r) { return r.first == key; });
  return it == table.end() ? nullptr : &it->second;
}

bool isConstructor(std::string_view name) {
  for (std::string_view prefix : {"vec", "ivec", "uvec", "bvec", "mat"})
    if (name.size() == prefix.size() + 1 && name.starts_with(prefix) && name.back() >= '2' && name.back() <= '4')
      return true;
  return false;
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\n' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\n' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

struct Range {
  std::size_t begin, end;  // token indices, end exclusive
};

class Translator {
 public:
  Translator(std::string_view glsl, const HlslTranslation& translation)
      : tokens_(tokenizeGlsl(glsl)), translation_(translation) {}

  std::string run() { return translate({0, tokens_.size()}); }

 private:
  std::string translate(Range range) const {
    std::string out;
    for (std::size_t i = range.begin; i < range.end;) i = translateAt(i, range.end, out);
    return out;
  }
  std::string translateTrimmed(Range range) const { return std::string(trim(translate(range))); }

  // Appends the translation of the token at i (and of any call or operand a rewrite
  // consumes with it); returns the index of the next token to translate.
  std::size_t translateAt(std::size_t i, std::size_t end, std::string& out) const {
    const GlslToken& token = tokens_[i];
    bool name = token.kind == GlslTokenKind::Identifier || token.kind == GlslTokenKind::Placeholder;
    if (!name || isMember(i)) {
      out += token.text;
      return i + 1;
    }
    if (std::size_t next = rewriteMatrixProduct(i, end, out)) return next;
    std::size_t open = nextSignificant(i + 1, end);
    if (open < end && isPunctuation(open, '(')) {
      std::size_t close = matchingClose(open, end);
      if (rewriteCall(token.text, open, close, out)) return close + 1;
    }
    if (token.text == "sampler2D" || token.text == "samplerCube")
      throw std::invalid_argument("GLSL to HLSL: " + std::string(token.text) + " outside texture()");
    out += renamed(token.text);
    return i + 1;
  }

  std::string_view renamed(std::string_view name) const {
    for (const auto& [from, to] : translation_.renames)
      if (from == name) return to;
    const std::string_view* mapped = lookup(kTokenMap, name);
    return mapped ? *mapped : name;
  }

  // "M * operand" with M a matrix: "mul(M, operand)".
  std::size_t rewriteMatrixProduct(std::size_t i, std::size_t end, std::string& out) const {
    const auto& matrices = translation_.matrices;
    if (std::find(matrices.begin(), matrices.end(), tokens_[i].text) == matrices.end()) return 0;
    std::size_t star = nextSignificant(i + 1, end);
    if (star >= end || !isPunctuation(star, '*') || (star + 1 < end && isPunctuation(star + 1, '='))) return 0;
    Range operand{star + 1, unaryEnd(nextSignificant(star + 1, end), end)};
    out += "mul(" + std::string(renamed(tokens_[i].text)) + ", " + translateTrimmed(operand) + ")";
    return operand.end;
  }

  // Rewrites a call spelled differently in HLSL; false leaves it to the token map.
  bool rewriteCall(std::string_view callee, std::size_t open, std::size_t close, std::string& out) const {
    std::vector<Range> args = arguments(open, close);
    if (isConstructor(callee) && args.size() == 1) {
      out += "((" + std::string(renamed(callee)) + ")(" + translateTrimmed(args[0]) + "))";
      return true;
    }
    if (const std::string_view* op = lookup(kComparisons, callee); op && args.size() == 2) {
      out += "(" + translateTrimmed(args[0]) + " " + std::string(*op) + " " + translateTrimmed(args[1]) + ")";
      return true;
    }
    if (callee == "not" && args.size() == 1) {
      out += "(!" + translateTrimmed(args[0]) + ")";
      return true;
    }
    if (callee == "atan" && args.size() == 2) {
      out += "atan2(" + translate({open + 1, close}) + ")";
      return true;
    }
    if (const std::string_view* method = lookup(kSamplingMethods, callee); method && args.size() >= 2)
      return rewriteSampling(*method, args, close, out);
    return false;
  }

  // texture(sampler2D(t, s), rest) -> t.Sample(s, rest); samplerCube the same.
  bool rewriteSampling(std::string_view method, const std::vector<Range>& args, std::size_t close,
                       std::string& out) const {
    std::size_t callee = nextSignificant(args[0].begin, args[0].end);
    if (callee >= args[0].end || (tokens_[callee].text != "sampler2D" && tokens_[callee].text != "samplerCube"))
      return false;
    std::size_t open = nextSignificant(callee + 1, args[0].end);
    if (open >= args[0].end || !isPunctuation(open, '(')) return false;
    std::vector<Range> pair = arguments(open, matchingClose(open, args[0].end));
    if (pair.size() != 2) return false;
    out += translateTrimmed(pair[0]) + "." + std::string(method) + "(" + translateTrimmed(pair[1]) + "," +
           translate({args[0].end + 1, close}) + ")";
    return true;
  }

  // The end of a unary expression starting at i: prefix operators, a primary, then
  // postfix calls, subscripts and member accesses.
  std::size_t unaryEnd(std::size_t i, std::size_t end) const {
    while (i < end && tokens_[i].kind == GlslTokenKind::Punctuation && std::string_view("-+!~").find(tokens_[i].text[0]) != std::string_view::npos)
      i = nextSignificant(i + 1, end);
    if (i >= end) return end;
    i = isPunctuation(i, '(') ? matchingClose(i, end) + 1 : i + 1;
    while (i < end) {
      if (isPunctuation(i, '(') || isPunctuation(i, '[')) i = matchingClose(i, end) + 1;
      else if (isPunctuation(i, '.') && i + 1 < end) i += 2;
      else break;
    }
    return i;
  }

  std::vector<Range> arguments(std::size_t open, std::size_t close) const {
    std::vector<Range> args;
    std::size_t begin = open + 1;
    int depth = 0;
    for (std::size_t i = open + 1; i < close; ++i) {
      if (isPunctuation(i, '(') || isPunctuation(i, '[')) ++depth;
      else if (isPunctuation(i, ')') || isPunctuation(i, ']')) --depth;
      else if (depth == 0 && isPunctuation(i, ',')) {
        args.push_back({begin, i});
        begin = i + 1;
      }
    }
    if (begin < close || !args.empty()) args.push_back({begin, close});
    return args;
  }

  std::size_t matchingClose(std::size_t open, std::size_t end) const {
    int depth = 0;
    for (std::size_t i = open; i < end; ++i) {
      if (isPunctuation(i, '(') || isPunctuation(i, '[')) ++depth;
      else if ((isPunctuation(i, ')') || isPunctuation(i, ']')) && --depth == 0) return i;
    }
    throw std::invalid_argument("GLSL to HLSL: unbalanced parentheses");
  }

  std::size_t nextSignificant(std::size_t i, std::size_t end) const {
    while (i < end && tokens_[i].kind == GlslTokenKind::Space) ++i;
    return i;
  }

  // A name after '.' is a swizzle or member, spelled alike in both languages.
  bool isMember(std::size_t i) const {
    while (i > 0 && tokens_[i - 1].kind == GlslTokenKind::Space) --i;
    return i > 0 && isPunctuation(i - 1, '.');
  }

  bool isPunctuation(std::size_t i, char c) const {
    return tokens_[i].kind == GlslTokenKind::Punctuation && tokens_[i].text[0] == c;
  }

  std::vector<GlslToken> tokens_;
  const HlslTranslation& translation_;
};

}  // namespace

std::string glslToHlsl(std::string_view glsl, const HlslTranslation& translation) {
  return Translator(glsl, translation).run();
}

bool callsHlslPrelude(std::string_view hlsl) { return hlsl.find("wg_glsl_") != std::string_view::npos; }

std::string_view hlslPrelude() {
  // Functions, not a macro: no generated code defines macros.
  return "// GLSL's mod: the result has the sign of y (HLSL's fmod gives it the sign of x).\n"
         "float wg_glsl_mod(float x, float y) { return x - y * floor(x / y); }\n"
         "float2 wg_glsl_mod(float2 x, float2 y) { return x - y * floor(x / y); }\n"
         "float3 wg_glsl_mod(float3 x, float3 y) { return x - y * floor(x / y); }\n"
         "float4 wg_glsl_mod(float4 x, float4 y) { return x - y * floor(x / y); }\n"
         "float2 wg_glsl_mod(float2 x, float y) { return x - y * floor(x / y); }\n"
         "float3 wg_glsl_mod(float3 x, float y) { return x - y * floor(x / y); }\n"
         "float4 wg_glsl_mod(float4 x, float y) { return x - y * floor(x / y); }\n";
}

}  // namespace wg
