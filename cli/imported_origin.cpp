#include "cli/imported_origin.hpp"

#include <filesystem>

namespace wg {

namespace {
void replaceAll(std::string& text, const std::string& from, const std::string& to) {
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
}
}  // namespace

std::vector<Diagnostic> inModelTerms(std::vector<Diagnostic> diagnostics, const std::vector<ImportedOrigin>& origins) {
  for (auto& d : diagnostics)
    for (const auto& origin : origins) {
      if (d.location.file == origin.path) d.location = origin.at;
      // The whole path first: the compiler names an image by the path it opened.
      for (const std::string& name : {origin.path, std::filesystem::path(origin.path).filename().string()}) {
        replaceAll(d.message, name, origin.what);
        replaceAll(d.hint, name, origin.what);
      }
    }
  return diagnostics;
}

}  // namespace wg
