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
#include "nodes/shader_stage.hpp"

namespace wg {

std::string writeSurface(const IrGraph& graph, const SurfaceInterface& surface, SurfaceLanguage language,
                         std::string_view contentHash, const std::vector<std::string>& nodeNames);

// One stage of the surface as a host embeds it in a shader of its own, after declaring
// every resource itself (what WG_HOST_DECLARES_RESOURCES asks of a host): the library
// code the stage and hostCalls reach, the stage's two structs and its function. The
// full shaders are this plus the reference host (backends/reference_host.hpp).
std::string writeEmbeddedSurfaceStage(const IrGraph& graph, const SurfaceInterface& surface, ShaderLanguage language,
                                      ShaderStage stage, const std::vector<std::string>& nodeNames,
                                      const std::vector<std::string_view>& hostCalls);

}  // namespace wg
