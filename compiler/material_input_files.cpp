#include "compiler/material_input_files.hpp"

#include <set>

namespace wg {

std::vector<std::string> materialInputFiles(const IrGraph& ir) {
  std::set<std::string> files(ir.includedFiles.begin(), ir.includedFiles.end());
  for (const auto& t : ir.textures)
    if (!t.file.empty()) files.insert(t.resolvedPath);
  return {files.begin(), files.end()};
}

}  // namespace wg
