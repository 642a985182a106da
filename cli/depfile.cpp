#include "cli/depfile.hpp"

namespace wg {

namespace {
std::string escapeForMake(const std::string& path) {
  std::string out;
  for (char c : path) {
    if (c == ' ' || c == '#' || c == '\\') out += '\\';
    if (c == '$') out += '$';
    out += c;
  }
  return out;
}
}  // namespace

std::string formatDepfile(const std::vector<DepfileRule>& rules) {
  std::string out;
  for (const auto& rule : rules) {
    for (std::size_t i = 0; i < rule.outputs.size(); ++i) out += (i ? " " : "") + escapeForMake(rule.outputs[i]);
    out += ":";
    for (const auto& input : rule.inputs) out += " \\\n  " + escapeForMake(input);
    out += "\n";
  }
  return out;
}

}  // namespace wg
