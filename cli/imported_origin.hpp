// `render --model` imports the model's materials and images into a temporary folder and
// compiles them from there. A diagnostic about one of those files names what the user
// made instead: the model, the JSON pointer and line of the material or image.
#pragma once
#include <string>
#include <vector>

#include "compiler/diagnostic.hpp"

namespace wg {

// Where a file of the temporary folder came from in the user's model.
struct ImportedOrigin {
  std::string path;   // the temporary file
  SourceLocation at;  // in the model
  std::string what;   // "material 2 (Steel)", "image 0 (rust.png)"
};

// The diagnostics with every temporary file replaced by its origin: the location becomes
// the model's, and the file's name in the message and hint becomes what it was made from.
std::vector<Diagnostic> inModelTerms(std::vector<Diagnostic> diagnostics, const std::vector<ImportedOrigin>& origins);

}  // namespace wg
