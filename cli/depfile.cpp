#include "cli/depfile.hpp"

#include "compiler/literal.hpp"

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

bool expressible(const std::string& path) {
  for (char c : path) {
    auto u = static_cast<unsigned char>(c);
    if (u < 0x20 || u == 0x7f || c == ':') return false;
  }
  return true;
}
}  // namespace

std::optional<std::string> formatDepfile(const std::vector<DepfileRule>& rules, std::string& error) {
  for (const auto& rule : rules)
    for (const auto* list : {&rule.outputs, &rule.inputs})
      for (const auto& path : *list)
        if (!expressible(path)) {
          error = "the path '" + quoteUserText(path, 200) +
                  "' holds a control character or ':', which a Make depfile cannot express safely; rename it or drop --depfile";
          return std::nullopt;
        }
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
