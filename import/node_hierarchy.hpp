// glTF nodes must form strict trees (glTF 2.0, 3.5.3): one parent at most, never their
// own ancestor, and a scene lists only roots. Checked once, so every traversal after it
// is finite and visits each node once per scene (no exponential blow-up from shared
// children).
#pragma once
#include "compiler/diagnostic.hpp"
#include "import/gltf_asset.hpp"

namespace wg::gltf {

// Reports WG5006; returns false on error.
bool checkNodeHierarchy(const Asset& asset, DiagnosticList& diagnostics);

}  // namespace wg::gltf
