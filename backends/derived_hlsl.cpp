#include "backends/derived_hlsl.hpp"

#include <stdexcept>
#include <string>
#include <unordered_map>

#include "compiler/material_interface.hpp"
#include "nodes/op_registry.hpp"

namespace wg {

namespace {

// Built once, for every op and every library an op or a stage frame can use, so
// stages read it without locks.
struct DerivedHlsl {
  std::unordered_map<const ShaderLibrary*, std::string> libraries;
  std::unordered_map<const ShaderLibrary*, bool> librariesCallingPrelude;  // scanned once, not per stage
  std::unordered_map<const OpDef*, std::string> ops;

  DerivedHlsl() {
    for (const OpDef* op : allOps())
      ops.emplace(op, op->hlsl.empty() ? glslToHlsl(op->glsl, frameMatrixTranslation()) : std::string(op->hlsl));
    for (const ShaderLibrary* library : allShaderLibraries()) {
      std::string hlsl = glslToHlsl(library->glsl, frameMatrixTranslation());
      librariesCallingPrelude.emplace(library, callsHlslPrelude(hlsl));
      libraries.emplace(library, std::move(hlsl));
    }
  }
};

const DerivedHlsl& derived() {
  static const DerivedHlsl instance;
  return instance;
}

template <class Map, class Key>
std::string_view find(const Map& map, const Key* key, std::string_view name) {
  auto it = map.find(key);
  if (it == map.end()) throw std::logic_error("no derived HLSL for " + std::string(name) + ": not reachable from the op registry");
  return it->second;
}

}  // namespace

const HlslTranslation& frameMatrixTranslation() {
  static const HlslTranslation instance = [] {
    HlslTranslation translation;
    for (const BlockMember& member : frameBlock().members)
      if (member.type == InterfaceType::Mat4) translation.matrices.push_back(member.identifier);
    return translation;
  }();
  return instance;
}

std::string_view derivedHlsl(const ShaderLibrary& library) { return find(derived().libraries, &library, library.name); }
std::string_view derivedHlsl(const OpDef& op) { return find(derived().ops, &op, op.name); }
bool derivedHlslCallsPrelude(const ShaderLibrary& library) {
  find(derived().libraries, &library, library.name);  // the same error for an unreachable library
  return derived().librariesCallingPrelude.at(&library);
}

}  // namespace wg
