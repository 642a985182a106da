#include "cli/picture_files.hpp"

#include <map>
#include <memory>

#include "cli/staged_directory.hpp"
#include "compiler/literal.hpp"
#include "host/image/png_file.hpp"

namespace wg {

namespace {
std::filesystem::path folderOf(const std::filesystem::path& file) {
  return file.has_parent_path() ? file.parent_path() : std::filesystem::path(".");
}
}  // namespace

std::string writePicturesTogether(const std::vector<PictureFile>& pictures) {
  std::map<std::filesystem::path, std::unique_ptr<StagedDirectory>> folders;
  for (const auto& [path, picture, createFolder] : pictures) {
    const std::string name = path.filename().string();
    if (name.empty() || name == "." || name == "..")
      return "cannot write '" + quoteUserText(path.string(), 300) + "': not a file name";
    std::error_code ec;
    if (!createFolder && !std::filesystem::is_directory(folderOf(path), ec))
      return "cannot write '" + quoteUserText(path.string(), 300) + "': no folder '" +
             quoteUserText(folderOf(path).string(), 300) + "'";
    std::string bytes;
    if (std::string e = image::encodePng(picture, bytes); !e.empty())
      return "cannot write '" + quoteUserText(path.string(), 300) + "': " + e;
    auto& folder = folders[folderOf(path)];
    if (!folder) folder = std::make_unique<StagedDirectory>(folderOf(path));
    if (std::string e = folder->stage(name, bytes); !e.empty()) return e;
  }
  for (auto& [dir, folder] : folders)
    if (std::string e = folder->readyToPublish(); !e.empty()) return e;
  for (auto& [dir, folder] : folders)
    if (std::string e = folder->publish(); !e.empty()) return e;
  return "";
}

}  // namespace wg
