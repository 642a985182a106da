// docs/diagnostics.md, generated from the one diagnostic table; a test keeps the
// checked-in file equal to this output.
#pragma once
#include <string>

namespace wg {

std::string diagnosticsMarkdown();

}  // namespace wg
