// All-or-nothing output: files are written into a private staging folder inside the
// output directory (created exclusively, so nothing planted there is followed), and
// only when every one of them is written and synced to disk are they renamed into
// place. A failed run leaves the output directory as it was. An output that already
// holds the same bytes and is ours to touch is not written again; publishing touches it.
#pragma once
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace wg {

class StagedDirectory {
 public:
  explicit StagedDirectory(std::filesystem::path directory) : directory_(std::move(directory)) {}
  ~StagedDirectory();
  StagedDirectory(const StagedDirectory&) = delete;
  StagedDirectory& operator=(const StagedDirectory&) = delete;

  // Each returns "" or a one-line error with the system's reason.
  std::string stage(const std::string& name, std::string_view bytes);
  // Syncs the staged files and checks that no directory holds an output's name: what can
  // fail before the first rename. publish() does it too; a run publishing several
  // folders together asks each first, so a failure in one leaves all as they were.
  std::string readyToPublish();
  std::string publish();

 private:
  std::string ensureStaging();
  std::string syncStaged();
  std::filesystem::path directory_, staging_;
  std::vector<std::string> names_;
  std::vector<std::string> unchanged_;  // already hold their bytes: touched on publishing
  std::vector<std::filesystem::path> created_;  // folders this run made, deepest last
  bool ready_ = false;
  bool published_ = false;
};

}  // namespace wg
