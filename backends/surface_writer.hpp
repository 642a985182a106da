// Writes a material's weathered surface (--target surface): the vertex and fragment
// functions of its SurfaceInterface, with the structs and resources they read, and no
// main, camera or lighting. Each surface file can share a shader with others: library
// functions and the weather's declarations are guarded so they appear once, and every
// resource's set and binding is a macro a host may define first.
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "compiler/ir.hpp"
#include "compiler/surface_interface.hpp"

namespace wg {

std::string writeSurface(const IrGraph& graph, const SurfaceInterface& surface, SurfaceLanguage language,
                         std::string_view contentHash, const std::vector<std::string>& nodeNames);

}  // namespace wg
