#include "cli/depfile.hpp"

#include "compiler/literal.hpp"

namespace wg {

namespace {
std::string escapeForMake(const std::string& path) {
  std::string out;
  for (char c : path) {
    if (c == ' ' || c == '#') out += '\\';
    if (c == '$') out += '$';
    out += c;
  }
  return out;
}

// Bytes both GNU make and Ninja's depfile parser read literally, unescaped: Ninja ends
// a name at anything else, and make gives ';' '|' '*' '?' and quotes meanings of their
// own (';' starts a recipe). ' ', '#' and '$' are escaped above; the rest is refused.
bool expressible(const std::string& path) {
  constexpr std::string_view kLiteral = "+,/_.~(){}%=@[]!- #$";
  for (char c : path) {
    auto u = static_cast<unsigned char>(c);
    const bool alnum = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9');
    if (!alnum && u < 0x80 && kLiteral.find(c) == std::string_view::npos) return false;
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
                  "' holds a character that make or Ninja would misread in a depfile (a control character, or one of : ; | * ? \\ \" ' ` & < > ^); rename it or drop --depfile";
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
