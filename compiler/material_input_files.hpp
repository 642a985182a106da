// The files a graph's compile read besides the graph itself: the graph libraries it
// includes and the image files its textures load. Depfiles list them, and
// `render --watch` polls them.
#pragma once
#include <string>
#include <vector>

#include "compiler/ir.hpp"

namespace wg {

// Resolved paths, sorted, each once.
std::vector<std::string> materialInputFiles(const IrGraph& ir);

}  // namespace wg
