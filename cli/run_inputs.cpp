#include "cli/run_inputs.hpp"

#include <sys/stat.h>

#include "compiler/literal.hpp"

namespace wg {

namespace {
std::string replacesMessage(const PlannedOutput& output, const std::string& input) {
  const std::string written = quoteUserText(output.path.string(), 300);
  const std::string also = output.path.string() == input ? "" : ", which is '" + quoteUserText(input, 300) + "'";
  return output.option + " writes '" + written + "'" + also + ", a file this run reads; choose another output path";
}

// What a path names when it is neither a regular file nor a directory, or nullptr.
const char* specialFileKind(mode_t mode) {
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISSOCK(mode)) return "a socket";
  return nullptr;
}

std::string specialFileMessage(const PlannedOutput& output, const char* kind) {
  return output.option + " writes '" + quoteUserText(output.path.string(), 300) + "', which is " + kind +
         ", not a regular file; name a regular file";
}
}  // namespace

void RunInputs::add(const std::filesystem::path& input) {
  struct stat st {};
  if (::stat(input.c_str(), &st) != 0) return;
  inputs_.push_back({st.st_dev, st.st_ino, input.string()});
}

void RunInputs::add(const std::vector<std::string>& inputs) {
  for (const auto& input : inputs) add(std::filesystem::path(input));
}

void RunInputs::add(const std::vector<std::filesystem::path>& inputs) {
  for (const auto& input : inputs) add(input);
}

std::string RunInputs::checkOutputs(const std::vector<PlannedOutput>& outputs) const {
  for (const auto& output : outputs) {
    struct stat st {};
    if (::stat(output.path.c_str(), &st) != 0) continue;  // a new file replaces nothing
    for (const auto& input : inputs_)
      if (input.device == st.st_dev && input.inode == st.st_ino) return replacesMessage(output, input.path);
  }
  return "";
}

std::string checkNoSpecialFiles(const std::vector<PlannedOutput>& outputs) {
  for (const auto& output : outputs) {
    struct stat st {};
    if (::stat(output.path.c_str(), &st) != 0) continue;
    if (const char* kind = specialFileKind(st.st_mode)) return specialFileMessage(output, kind);
  }
  return "";
}

}  // namespace wg
