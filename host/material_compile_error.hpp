// Thrown when a scene's material graph does not compile. It carries the compiler's
// diagnostics as values, so a command can print them as `compile` does (file:line:col,
// code, pointer, hint) and exit with "bad input" instead of "internal error".
#pragma once
#include <stdexcept>
#include <string>
#include <vector>

#include "compiler/diagnostic.hpp"

namespace wg {

class MaterialCompileError : public std::runtime_error {
 public:
  MaterialCompileError(const std::string& graphPath, std::vector<Diagnostic> diagnostics);
  const std::vector<Diagnostic>& diagnostics() const { return diagnostics_; }

 private:
  std::vector<Diagnostic> diagnostics_;
};

}  // namespace wg
