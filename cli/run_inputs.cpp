#include "cli/run_inputs.hpp"

#include <sys/stat.h>

#include "compiler/literal.hpp"

namespace wg {

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
      if (input.device == st.st_dev && input.inode == st.st_ino)
        return output.option + " writes '" + quoteUserText(output.path.string(), 300) + "', which is '" +
               quoteUserText(input.path, 300) + "', a file this run reads; choose another output path";
  }
  return "";
}

}  // namespace wg
