#include "cli/file_stamps.hpp"

#include <filesystem>

namespace wg {

namespace {
std::string stampOf(const std::string& path) {
  std::error_code ec;
  auto time = std::filesystem::last_write_time(path, ec);
  if (ec) return "missing";
  auto size = std::filesystem::file_size(path, ec);
  if (ec) return "missing";
  return std::to_string(time.time_since_epoch().count()) + " " + std::to_string(size);
}
}  // namespace

FileStamps::FileStamps(const std::vector<std::string>& files) {
  for (const auto& f : files) stamps_[f] = stampOf(f);
}

FileStamps::FileStamps(const std::vector<std::string>& files, const FileStamps& earlier) {
  for (const auto& f : files) {
    auto it = earlier.stamps_.find(f);
    stamps_[f] = it != earlier.stamps_.end() ? it->second : stampOf(f);
  }
}

std::string FileStamps::firstChanged() const {
  for (const auto& [path, stamp] : stamps_)
    if (stampOf(path) != stamp) return path;
  return "";
}

}  // namespace wg
