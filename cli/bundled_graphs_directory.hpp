// Where `render` and `bench-render` find the bundled graphs by default. The path is
// resolved next to the running executable, not compiled in, so in-tree builds of any
// checkout are byte-identical and share build caches (docs/scaling.md).
#pragma once
#include <string>

namespace wg {

// <exe dir>/<path from the build dir to graphs/>, else <exe dir>/../share/weathergen/graphs
// (an installed weathergen); "" when neither exists.
std::string bundledGraphsDirectory();

}  // namespace wg
