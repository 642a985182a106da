#include "compiler/cpp_header.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <string_view>
#include <vector>

#include "compiler/identifier.hpp"
#include "compiler/name_mark.hpp"

namespace wg {

namespace {

// C++20 keywords and alternative tokens, contextual names, and the lowercase macros an
// including translation unit may see (<cstddef>, <cassert>, <cerrno>, GNU mode's
// 'linux'/'unix'). IdentifierScope already avoids GLSL/HLSL words; these are C++'s own.
constexpr std::array<std::string_view, 104> kCppReserved = {
    "alignas", "alignof", "and", "and_eq", "asm", "auto", "bitand", "bitor", "bool", "break", "case", "catch",
    "char", "char8_t", "char16_t", "char32_t", "class", "compl", "concept", "const", "consteval", "constexpr",
    "constinit", "const_cast", "continue", "co_await", "co_return", "co_yield", "decltype", "default", "delete",
    "do", "double", "dynamic_cast", "else", "enum", "explicit", "export", "extern", "false", "float", "for",
    "friend", "goto", "if", "inline", "int", "long", "mutable", "namespace", "new", "noexcept", "not", "not_eq",
    "nullptr", "operator", "or", "or_eq", "private", "protected", "public", "register", "reinterpret_cast",
    "requires", "return", "short", "signed", "sizeof", "static", "static_assert", "static_cast", "struct",
    "switch", "template", "this", "thread_local", "throw", "true", "try", "typedef", "typeid", "typename",
    "union", "unsigned", "using", "virtual", "void", "volatile", "wchar_t", "while", "xor", "xor_eq",
    // contextual identifiers and names this header relies on
    "final", "override", "import", "module", "std", "weathergen_materials",
    // lowercase macros
    "offsetof", "assert", "errno", "linux", "unix", "i386",
};

// std140 rounds every block up to a vec4; alignas makes C++ agree for arrays of blocks.
constexpr std::uint32_t kStd140BlockAlignment = 16;

IdentifierScope cppScope() {
  IdentifierScope scope;
  for (std::string_view word : kCppReserved) scope.reserve(word);
  return scope;
}

// The C++ spelling of a std140 member: scalars, or float arrays for vectors and the
// column-major mat4 (four vec4 columns, which std140 packs without gaps).
struct CppType {
  std::string_view scalar;
  std::uint32_t count;  // 1: no array
};
CppType cppTypeOf(InterfaceType type) {
  switch (type) {
    case InterfaceType::Float: return {"float", 1};
    case InterfaceType::Vec2: return {"float", 2};
    case InterfaceType::Vec3: return {"float", 3};
    case InterfaceType::Vec4: return {"float", 4};
    case InterfaceType::Uint: return {"std::uint32_t", 1};
    case InterfaceType::Mat4: return {"float", 16};
  }
  return {"float", 1};
}

std::string declaration(std::string_view type, const std::string& name, std::uint32_t count) {
  std::string out = "  " + std::string(type) + " " + name;
  if (count > 1) out += "[" + std::to_string(count) + "]";
  return out + ";";
}

// One struct, padded by hand so every member sits at its std140 offset whatever the
// C++ compiler's own packing would be, followed by the asserts that prove it.
std::string emitBlockStruct(const UniformBlock& block, std::string_view purpose) {
  IdentifierScope scope = cppScope();
  // Members are named first so padding can never take a member's name. They keep the
  // reflection's identifiers, so engines match them by name; one would only change if
  // it were a C++ word, and none is: they all start with "frame_", "weather_" or "mat_".
  std::vector<std::string> names;
  for (const BlockMember& m : block.members) names.push_back(scope.make(m.identifier));
  std::string body, asserts;
  std::uint32_t cursor = 0;
  auto pad = [&](std::uint32_t to) {
    if (to == cursor) return;
    body += declaration("std::uint8_t", scope.make("pad"), to - cursor) + "  // std140 padding\n";
    cursor = to;
  };
  for (std::size_t i = 0; i < block.members.size(); ++i) {
    const BlockMember& m = block.members[i];
    pad(m.offset);
    CppType type = cppTypeOf(m.type);
    body += declaration(type.scalar, names[i], type.count) + "  // " + std::string(interfaceTypeName(m.type)) +
            ", offset " + std::to_string(m.offset) + "\n";
    asserts += "static_assert(offsetof(" + block.identifier + ", " + names[i] + ") == " + std::to_string(m.offset) +
               ", \"" + block.identifier + "::" + names[i] + " is not at its std140 offset\");\n";
    cursor = m.offset + m.size;
  }
  pad(block.size);
  asserts += "static_assert(sizeof(" + block.identifier + ") == " + std::to_string(block.size) + ", \"" +
             block.identifier + " is not its std140 size\");\n";
  return "// " + std::string(purpose) + ": set " + std::to_string(block.set) + ", binding " +
         std::to_string(block.binding) + ", std140, " + std::to_string(block.size) + " bytes.\n" + "struct alignas(" +
         std::to_string(kStd140BlockAlignment) + ") " + block.identifier + " {\n" + body + "};\n" + asserts;
}

std::string constant(std::string_view name, std::uint32_t value) {
  return "inline constexpr std::uint32_t " + std::string(name) + " = " + std::to_string(value) + ";\n";
}

std::string textureSlots(const std::vector<TextureBinding>& bindings, std::string_view purpose,
                         IdentifierScope& scope) {
  if (bindings.empty()) return "";
  std::string out = "// " + std::string(purpose) + "\n";
  for (const TextureBinding& b : bindings)
    out += "inline constexpr TextureSlot " + scope.make(b.textureIdentifier) + "{" + std::to_string(b.set) + ", " +
           std::to_string(b.textureBinding) + ", " + std::to_string(b.samplerBinding) + "};\n";
  return out;
}

// The content hash is hex; anything else would be a bug, and must not reach a literal.
std::string hexOnly(const std::string& text) {
  std::string out;
  for (char c : text)
    if (std::isxdigit(static_cast<unsigned char>(c))) out += c;
  return out;
}

}  // namespace

// A clean identifier with a lower-case letter is kept; any other name is sanitised and
// marked with its hash ("_h" and 8 hex digits), so 'a-b' and 'a_b', 'class' and
// 'class_v', 'ROCK' and 'ROCK_material' get distinct namespaces in every run.
std::string cppMaterialNamespace(const std::string& materialName) {
  IdentifierScope scope = cppScope();
  const bool hasLower = std::any_of(materialName.begin(), materialName.end(),
                                    [](char c) { return std::islower(static_cast<unsigned char>(c)); });
  // Upper-case names are the macro convention (INT32_MAX...); they are marked too.
  const bool kept = hasLower && IdentifierScope::sanitize(materialName) == materialName &&
                    !endsWithNameMark(materialName, '_') && scope.make(materialName) == materialName;
  if (kept) return materialName;
  std::string base = IdentifierScope::sanitize(materialName);
  const std::string mark = "_" + nameMark(materialName);
  base.resize(std::min(base.size(), IdentifierScope::kMaxLength - mark.size()));  // the mark must survive
  while (!base.empty() && base.back() == '_') base.pop_back();  // no doubled underscore before it
  return scope.make((base.empty() ? "material" : base) + mark);
}

std::string emitCppHeader(const IrGraph& ir, const MaterialInterface& mi, const std::string& contentHash) {
  const bool hasMaterialBlock = !mi.material.members.empty();
  std::string out;
  out += "// Generated by weathergen " WEATHERGEN_VERSION "; do not edit.\n";
  out += "// Uniform blocks of one material as C++ structs with the std140 layout its shaders use.\n";
  out += "#pragma once\n#include <cstddef>\n#include <cstdint>\n\n";
  const std::string ns = "weathergen_materials::" + cppMaterialNamespace(ir.name);
  out += "namespace " + ns + " {\n\n";
  out += "inline constexpr char kContentHash[] = \"" + hexOnly(contentHash) + "\";\n";
  out += constant("kFrameSet", mi.frame->set) + constant("kFrameBinding", mi.frame->binding);
  out += "inline constexpr bool kHasMaterialBlock = " + std::string(hasMaterialBlock ? "true" : "false") +
         ";  // false: no parameters, no block\n";
  out += constant("kMaterialSet", mi.material.set) + constant("kMaterialBinding", mi.material.binding) + "\n";
  out += emitBlockStruct(*mi.frame, "Frame and weather values shared by every material") + "\n";
  if (hasMaterialBlock) out += emitBlockStruct(mi.material, "This material's parameters") + "\n";
  if (!mi.textures.empty() || !mi.weatherMaps.empty()) {
    out += "struct TextureSlot {\n  std::uint32_t set, textureBinding, samplerBinding;\n};\n";
    // One scope for both lists: every slot is a namespace-level constant.
    IdentifierScope slots = cppScope();
    out += textureSlots(mi.textures, "This material's textures and their samplers.", slots);
    out += textureSlots(mi.weatherMaps, "Shared weather maps this material samples.", slots);
    out += "\n";
  }
  out += "}  // namespace " + ns + "\n";
  return out;
}

}  // namespace wg
