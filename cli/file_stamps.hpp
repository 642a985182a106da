// What --watch compares to notice an edit: each file's modification time and size.
// A file that is missing has a stamp of its own, so deleting or creating it counts.
#pragma once
#include <map>
#include <string>
#include <vector>

namespace wg {

class FileStamps {
 public:
  FileStamps() = default;
  explicit FileStamps(const std::vector<std::string>& files);  // stamps them now
  // Stamps `files` now, except those `earlier` stamped, which keep their earlier stamp
  // (so an edit made since then still counts as a change).
  FileStamps(const std::vector<std::string>& files, const FileStamps& earlier);

  // The first watched file whose stamp differs from now, or "" when none.
  std::string firstChanged() const;
  const std::map<std::string, std::string>& stamps() const { return stamps_; }

 private:
  std::map<std::string, std::string> stamps_;  // path -> "mtime size", or "missing"
};

}  // namespace wg
