#include "compiler/identifier.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <unordered_set>

namespace wg {

namespace {
// GLSL 4.50 keywords and reserved words, HLSL keywords, and the intrinsics the
// emitted code calls, so a user name can never shadow one.
constexpr std::array<std::string_view, 307> kReserved = {
    // GLSL keywords
    "attribute", "const", "uniform", "varying", "buffer", "shared", "coherent", "volatile", "restrict",
    "readonly", "writeonly", "atomic_uint", "layout", "centroid", "flat", "smooth", "noperspective", "patch",
    "sample", "break", "continue", "do", "for", "while", "switch", "case", "default", "if", "else",
    "subroutine", "in", "out", "inout", "float", "double", "int", "void", "bool", "true", "false", "invariant",
    "precise", "discard", "return", "mat2", "mat3", "mat4", "dmat2", "dmat3", "dmat4", "mat2x2", "mat2x3",
    "mat2x4", "mat3x2", "mat3x3", "mat3x4", "mat4x2", "mat4x3", "mat4x4", "vec2", "vec3", "vec4", "ivec2",
    "ivec3", "ivec4", "bvec2", "bvec3", "bvec4", "dvec2", "dvec3", "dvec4", "uint", "uvec2", "uvec3", "uvec4",
    "lowp", "mediump", "highp", "precision", "sampler1D", "sampler2D", "sampler3D", "samplerCube",
    "sampler2DShadow", "texture2D", "texture3D", "textureCube", "sampler", "samplerShadow", "struct",
    // GLSL reserved for future use
    "common", "partition", "active", "asm", "class", "union", "enum", "typedef", "template", "this", "resource",
    "goto", "inline", "noinline", "public", "static", "extern", "external", "interface", "long", "short", "half",
    "fixed", "unsigned", "superp", "input", "output", "hvec2", "hvec3", "hvec4", "fvec2", "fvec3", "fvec4",
    "sampler3DRect", "filter", "image1D", "image2D", "image3D", "imageCube", "sizeof", "cast", "namespace",
    "using", "row_major", "column_major",
    // HLSL keywords
    "AppendStructuredBuffer", "BlendState", "Buffer", "ByteAddressBuffer", "cbuffer", "compile",
    "ConstantBuffer", "ConsumeStructuredBuffer", "DepthStencilState", "DepthStencilView", "dword", "export",
    "float1", "float2", "float3", "float4", "float2x2", "float3x3", "float4x4", "float3x4", "float4x3", "groupshared",
    "int2", "int3", "int4", "uint2", "uint3", "uint4", "bool2", "bool3", "bool4", "half2", "half3", "half4",
    "InputPatch", "line", "lineadj", "linear", "matrix", "min16float", "min10float", "min16int", "min12int",
    "min16uint", "nointerpolation", "OutputPatch", "packoffset", "pass", "pixelfragment", "PixelShader", "point",
    "PointStream", "RasterizerState", "RenderTargetView", "register", "RWBuffer", "RWByteAddressBuffer",
    "RWStructuredBuffer", "RWTexture1D", "RWTexture2D", "RWTexture3D", "SamplerState", "SamplerComparisonState",
    "snorm", "stateblock", "stateblock_state", "StructuredBuffer", "tbuffer", "technique", "technique10",
    "technique11", "Texture", "Texture1D", "Texture2D", "Texture3D", "TextureCube", "Texture2DArray", "triangle",
    "triangleadj", "TriangleStream", "unorm", "vector", "vertexfragment", "VertexShader", "string",
    "main", "NULL", "nullptr", "auto", "catch", "char", "const_cast", "delete", "dynamic_cast", "explicit",
    "friend", "mutable", "new", "operator", "private", "protected", "reinterpret_cast", "signed", "static_cast",
    "throw", "try", "typename", "virtual", "globallycoherent", "precise_", "in_", "out_",
    // intrinsics used by emitted code
    "abs", "clamp", "cos", "cross", "dot", "exp", "exp2", "floor", "fract", "frac", "inversesqrt", "rsqrt",
    "length", "lerp", "log", "log2", "max", "min", "mix", "mul", "normalize", "pow", "saturate", "sign", "sin",
    "smoothstep", "sqrt", "step", "texture", "textureLod", "Sample", "SampleLevel", "clip", "reflect",
    "transpose", "determinant", "ddx", "ddy", "dFdx", "dFdy", "fwidth", "any", "all", "asuint", "asfloat",
    "floatBitsToUint", "uintBitsToFloat", "round", "trunc", "ceil", "mod", "fmod", "atan", "atan2", "tan", "acos",
    "asin", "distance", "faceforward", "refract",
};

bool startsWithIgnoringCase(std::string_view s, std::string_view prefix) {
  if (s.size() < prefix.size()) return false;
  for (std::size_t i = 0; i < prefix.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(s[i])) != prefix[i]) return false;
  return true;
}
}  // namespace

bool IdentifierScope::isReserved(std::string_view name) {
  if (startsWithIgnoringCase(name, "gl_") || startsWithIgnoringCase(name, "sv_")) return true;
  if (name.starts_with('_') || name.find("__") != std::string_view::npos) return true;
  // Hashed: every emitted name is checked, and large graphs emit tens of thousands.
  static const std::unordered_set<std::string_view> kReservedSet(kReserved.begin(), kReserved.end());
  return kReservedSet.count(name) != 0;
}

std::string IdentifierScope::sanitize(std::string_view hint) {
  std::string out;
  out.reserve(std::min(hint.size(), kMaxLength));
  for (char c : hint) {
    if (out.size() >= kMaxLength) break;
    bool alnum = std::isalnum(static_cast<unsigned char>(c)) && static_cast<unsigned char>(c) < 0x80;
    if (alnum) out += c;
    else if (!out.empty() && out.back() != '_') out += '_';  // runs of other bytes become one '_'
  }
  while (!out.empty() && out.back() == '_') out.pop_back();
  if (out.empty()) out = "id";
  if (std::isdigit(static_cast<unsigned char>(out[0]))) out.insert(0, "n");
  if (isReserved(out)) out += "_v";  // "else" -> "else_v"; "gl_Position" -> "gl_Position_v" is still gl_:
  if (isReserved(out)) out.insert(0, "u");  // ... so prefix it: "ugl_Position_v"
  return out;
}

namespace {
// Already what sanitize would return: ASCII alphanumerics and single inner underscores,
// starting with a letter, short enough.
bool isCleanIdentifier(std::string_view s) {
  if (s.empty() || s.size() > IdentifierScope::kMaxLength || !std::isalpha(static_cast<unsigned char>(s[0])) ||
      s.back() == '_')
    return false;
  for (std::size_t i = 0; i < s.size(); ++i) {
    unsigned char c = static_cast<unsigned char>(s[i]);
    if (c >= 0x80 || !(std::isalnum(c) || c == '_')) return false;
    if (c == '_' && s[i - 1] == '_') return false;
  }
  return !IdentifierScope::isReserved(s);
}
}  // namespace

std::string IdentifierScope::make(std::string_view hint) {
  std::string base = isCleanIdentifier(hint) ? std::string(hint) : sanitize(hint);
  std::string name = base;
  for (int suffix = 2; used_.count(name) || isReserved(name); ++suffix) name = base + "_" + std::to_string(suffix);
  used_.insert(name);
  return name;
}

void IdentifierScope::reserve(std::string_view name) { used_.insert(std::string(name)); }

}  // namespace wg
