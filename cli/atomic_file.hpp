// Writes a file atomically: a temporary in the same directory, then rename, so a
// reader or an interrupted build never sees a half-written output.
#pragma once
#include <string>
#include <string_view>

namespace wg {

// Returns an error message, or "" on success. No temporary is left behind either way.
std::string writeFileAtomically(const std::string& path, std::string_view bytes);

}  // namespace wg
