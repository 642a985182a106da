// Make-syntax dependency files for Ninja, Make and CMake's add_custom_command(DEPFILE):
// every output of a material depends on its graph, its graph libraries and the image
// files it reads.
#pragma once
#include <optional>
#include <string>
#include <vector>

namespace wg {

struct DepfileRule {
  std::vector<std::string> outputs;
  std::vector<std::string> inputs;
};

// One rule per material, paths escaped for Make (spaces, '#', '$'). A path holding a
// control character (newline, tab, NUL...) or ':' cannot be written safely (a newline
// and a tab would start a recipe line that Make runs): nullopt, and `error` names it.
std::optional<std::string> formatDepfile(const std::vector<DepfileRule>& rules, std::string& error);

}  // namespace wg
