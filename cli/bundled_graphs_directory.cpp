#include "cli/bundled_graphs_directory.hpp"

#include <filesystem>

namespace wg {

std::string bundledGraphsDirectory() {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (ec) return "";
  fs::path dir = exe.parent_path();
  for (const fs::path& candidate : {dir / WG_GRAPHS_FROM_EXECUTABLE, dir / ".." / "share" / "weathergen" / "graphs"})
    if (fs::is_directory(candidate, ec)) return candidate.lexically_normal().string();
  return "";
}

}  // namespace wg
