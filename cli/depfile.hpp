// Make-syntax dependency files for Ninja, Make and CMake's add_custom_command(DEPFILE):
// every output of a material depends on its graph, its graph libraries and the image
// files it reads.
#pragma once
#include <string>
#include <vector>

namespace wg {

struct DepfileRule {
  std::vector<std::string> outputs;
  std::vector<std::string> inputs;
};

// One rule per material, paths escaped for Make (spaces, '#', '$').
std::string formatDepfile(const std::vector<DepfileRule>& rules);

}  // namespace wg
