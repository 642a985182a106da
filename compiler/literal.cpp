#include "compiler/literal.hpp"

#include <cmath>

namespace wg {

namespace {
std::optional<float> toFloat(const nlohmann::json& j, bool& notFinite) {
  if (!j.is_number()) return std::nullopt;
  double d = j.get<double>();
  float f = static_cast<float>(d);
  if (!std::isfinite(d) || !std::isfinite(f)) notFinite = true;
  return f;
}
}  // namespace

LiteralResult parseLiteral(const nlohmann::json& json) {
  LiteralResult result;
  if (json.is_boolean()) {
    result.value = Value::boolean(json.get<bool>());
    return result;
  }
  if (json.is_number()) {
    result.value = Value::scalar(*toFloat(json, result.notFinite));
    return result;
  }
  if (json.is_array()) {
    if (json.size() < 2 || json.size() > 4) {
      result.shapeError = "an array of " + std::to_string(json.size()) + " elements (vectors have 2 to 4)";
      return result;
    }
    Value v{floatVectorOfWidth(static_cast<int>(json.size())), {}};
    for (std::size_t i = 0; i < json.size(); ++i) {
      auto f = toFloat(json[i], result.notFinite);
      if (!f) {
        result.shapeError = "an array holding " + describeJsonKind(json[i]);
        return result;
      }
      v.v[i] = *f;
    }
    result.value = v;
    return result;
  }
  result.shapeError = describeJsonKind(json);
  return result;
}

std::string describeJsonKind(const nlohmann::json& json) {
  switch (json.type()) {
    case nlohmann::json::value_t::null: return "null";
    case nlohmann::json::value_t::object: return "an object";
    case nlohmann::json::value_t::array: return "an array";
    case nlohmann::json::value_t::string: return "a string";
    case nlohmann::json::value_t::boolean: return "a boolean";
    default: return "a number";
  }
}

std::string quoteUserText(std::string_view text, std::size_t maxShown) {
  std::string out;
  for (std::size_t i = 0; i < text.size() && i < maxShown; ++i) {
    unsigned char c = static_cast<unsigned char>(text[i]);
    // U+0080..U+009F (UTF-8 C2 80..C2 9F) are C1 controls: U+009B is a CSI to terminals.
    if (c == 0xC2 && i + 1 < text.size() && static_cast<unsigned char>(text[i + 1]) <= 0x9F &&
        static_cast<unsigned char>(text[i + 1]) >= 0x80) {
      static const char* hex = "0123456789abcdef";
      const unsigned char c1 = static_cast<unsigned char>(text[++i]);
      out += "\\u00";
      out += hex[c1 >> 4];
      out += hex[c1 & 15];
      continue;
    }
    if (c < 0x20 || c == 0x7f) {
      static const char* hex = "0123456789abcdef";
      out += "\\x";
      out += hex[c >> 4];
      out += hex[c & 15];
    } else {
      out += static_cast<char>(c);
    }
  }
  if (text.size() > maxShown) out += "...";
  return out;
}

}  // namespace wg
