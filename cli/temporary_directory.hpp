// A private directory under $TMPDIR that is removed with its contents when the last
// owner lets go (mkdtemp: created exclusively, mode 0700).
#pragma once
#include <filesystem>
#include <memory>
#include <string>

namespace wg {

class TemporaryDirectory {
 public:
  // Throws std::runtime_error with the system's reason when it cannot be created.
  static std::shared_ptr<TemporaryDirectory> create(const std::string& prefix);
  ~TemporaryDirectory();
  TemporaryDirectory(const TemporaryDirectory&) = delete;
  TemporaryDirectory& operator=(const TemporaryDirectory&) = delete;

  const std::filesystem::path& path() const { return path_; }

 private:
  explicit TemporaryDirectory(std::filesystem::path path) : path_(std::move(path)) {}
  std::filesystem::path path_;
};

}  // namespace wg
