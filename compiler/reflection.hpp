// The reflection JSON published next to each material: every parameter (type,
// offset, size, block, binding), every texture, the vertex inputs and the content hash.
// The runtime builds its layouts from this, never by hand.
#pragma once
#include <string>

#include "compiler/ir.hpp"
#include "compiler/material_interface.hpp"
#include "compiler/surface_interface.hpp"

namespace wg {

std::string buildReflectionJson(const IrGraph& graph, const MaterialInterface& interface,
                                const SurfaceInterface& surface, const std::string& contentHash,
                                const std::string& fileStem);

}  // namespace wg
