// A material for Google's Filament (--target filament): NAME.mat, for Debian's matc.
// Filament is a host of the surface contract like any other: its material() calls the
// surface's fragment function and hands the result to Filament's own lighting, its
// materialVertex() applies the surface's displacement, and every resource the surface
// reads (the weather block's members, the maps, the material's block and textures) is a
// Filament parameter of the same name.
#pragma once
#include <cstddef>
#include <string>
#include <string_view>

#include "compiler/ir.hpp"
#include "compiler/surface_interface.hpp"

namespace wg {

// Filament 1.9's limits on what a material declares: matc stops at 48 parameters (its
// MaterialBuilder's MAX_PARAMETERS_COUNT), samplers included, and a shader has 16
// samplers, of which Filament's own lighting takes 8 (matc warns beyond, and the
// backends do not bind them).
inline constexpr std::size_t kFilamentMaxParameters = 48;
inline constexpr std::size_t kFilamentMaterialSamplers = 8;

// The parameters a surface's Filament material declares, by where they come from.
struct FilamentParameterCount {
  std::size_t weatherFields = 0, materialParameters = 0, textures = 0, weatherMaps = 0;
  std::size_t samplers() const { return textures + weatherMaps; }
  std::size_t total() const { return weatherFields + materialParameters + samplers(); }
};
FilamentParameterCount countFilamentParameters(const SurfaceInterface& surface);

// esSurface: the material's GLSL ES surface text (its combined samplers are what
// Filament's sampler2d parameters are).
std::string writeFilamentMaterial(const IrGraph& graph, const SurfaceInterface& surface, std::string_view esSurface,
                                  std::string_view contentHash);

}  // namespace wg
