// The pictures one render writes together: a timeline's contact sheet, its strip and
// the --frames pictures. All of them are written or none: a failure (a directory with
// an output's name, a full disk) leaves every output and folder as it was.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "nodes/texture_image.hpp"

namespace wg {

struct PictureFile {
  std::filesystem::path path;
  Image picture;
  bool createFolder = false;  // --frames DIR is created; -o's folder must exist
};

// Stages every picture beside its final name (cli/staged_directory.hpp), then renames
// them into place. Returns "" or one line naming the file that could not be written.
std::string writePicturesTogether(const std::vector<PictureFile>& pictures);

}  // namespace wg
