#include "compiler/json_text.hpp"

namespace wg {

std::string escapeC1Controls(std::string text) {
  std::size_t at = text.find('\xC2');
  if (at == std::string::npos) return text;
  static const char* hex = "0123456789abcdef";
  std::string out = text.substr(0, at);
  for (; at < text.size(); ++at) {
    const unsigned char next = at + 1 < text.size() ? static_cast<unsigned char>(text[at + 1]) : 0;
    if (text[at] == '\xC2' && next >= 0x80 && next <= 0x9F) {
      out += "\\u00";
      out += hex[next >> 4];
      out += hex[next & 15];
      ++at;
    } else {
      out += text[at];
    }
  }
  return out;
}

std::string jsonText(const nlohmann::json& value, int indent) {
  return escapeC1Controls(value.dump(indent, ' ', false, nlohmann::json::error_handler_t::replace));
}

std::string jsonText(const nlohmann::ordered_json& value, int indent) {
  return escapeC1Controls(value.dump(indent, ' ', false, nlohmann::ordered_json::error_handler_t::replace));
}

}  // namespace wg
