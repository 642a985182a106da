#include "host/material_compile_error.hpp"

namespace wg {

namespace {
std::string describe(const std::string& graphPath, const std::vector<Diagnostic>& diagnostics) {
  std::string message = "cannot compile " + graphPath + ":\n";
  for (const auto& d : diagnostics) message += formatDiagnosticText(d);
  return message;
}
}  // namespace

MaterialCompileError::MaterialCompileError(const std::string& graphPath, std::vector<Diagnostic> diagnostics)
    : std::runtime_error(describe(graphPath, diagnostics)), diagnostics_(std::move(diagnostics)) {}

}  // namespace wg
