// A material for Google's Filament (--target filament): NAME.mat, for Debian's matc.
// Filament is a host of the surface contract like any other: its material() calls the
// surface's fragment function and hands the result to Filament's own lighting, its
// materialVertex() applies the surface's displacement, and every resource the surface
// reads (the weather block's members, the maps, the material's block and textures) is a
// Filament parameter of the same name.
#pragma once
#include <string>
#include <string_view>

#include "compiler/ir.hpp"
#include "compiler/surface_interface.hpp"

namespace wg {

// esSurface: the material's GLSL ES surface text (its combined samplers are what
// Filament's sampler2d parameters are).
std::string writeFilamentMaterial(const IrGraph& graph, const SurfaceInterface& surface, std::string_view esSurface,
                                  std::string_view contentHash);

}  // namespace wg
