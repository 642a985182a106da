// Shared helpers for the benchmarks: the bundled graphs, found at run time.
#pragma once
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#ifndef WG_SOURCE_DIR
#error "WG_SOURCE_DIR must name the project source directory"
#endif

namespace wg::bench {

struct BundledGraph {
  std::string stem;  // "rock"
  std::string path;  // absolute
};

inline std::filesystem::path graphsDirectory() { return std::filesystem::path(WG_SOURCE_DIR) / "graphs"; }

// graphs/*.json, sorted by name (the schema directory and other files are skipped).
inline std::vector<BundledGraph> bundledGraphs() {
  std::vector<BundledGraph> out;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(graphsDirectory(), ec))
    if (entry.is_regular_file() && entry.path().extension() == ".json")
      out.push_back({entry.path().stem().string(), entry.path().string()});
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.stem < b.stem; });
  return out;
}

inline std::string readText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace wg::bench
