// A C++ header for engines: the frame/weather block and the material parameter block as
// plain structs laid out exactly like std140, with a static_assert on every offset and
// size, plus the descriptor set and binding numbers. Uploading such a struct with one
// memcpy then fills the uniform buffer the shaders read.
#pragma once
#include <string>

#include "compiler/ir.hpp"
#include "compiler/material_interface.hpp"

namespace wg {

// The header's text. Every name in it is an emitted identifier (IdentifierScope),
// never user text; the namespace is weathergen_materials::<cppMaterialNamespace(ir)>.
std::string emitCppHeader(const IrGraph& ir, const MaterialInterface& mi, const std::string& contentHash);

// The material's namespace inside weathergen_materials: its name made a safe C++
// identifier (no keyword, nothing shaped like a macro).
std::string cppMaterialNamespace(const std::string& materialName);

}  // namespace wg
