// Running the CLI and the independent validators from tests, and temp directories.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

namespace wg::testing {

struct CommandResult {
  int exitCode = -1;
  std::string output;  // stdout and stderr together
};

// Prefix for a command line that runs the CLI on Vulkan. Under the sanitizer pass the
// child unloads lavapipe before LeakSanitizer runs, so the driver's one-off allocations
// cannot be suppressed by name there (the same code is leak-checked in-process by the
// render tests); ASan and UBSan stay on.
inline constexpr const char* kVulkanChildEnvironment = "ASAN_OPTIONS=detect_leaks=0:abort_on_error=1 ";

// Runs a shell command; arguments must already be quoted with shellQuote.
CommandResult runCommand(const std::string& command);
std::string shellQuote(const std::string& text);

// A fresh empty directory under the system temp dir, removed by the destructor.
class TempDir {
 public:
  explicit TempDir(const std::string& tag);
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

std::string readFile(const std::filesystem::path& path);
void writeFile(const std::filesystem::path& path, const std::string& bytes);
std::vector<std::filesystem::path> bundledGraphs();  // graphs/*.json, sorted
std::vector<std::string> listFiles(const std::filesystem::path& dir);  // file names, sorted

}  // namespace wg::testing
