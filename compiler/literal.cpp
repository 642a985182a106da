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

namespace {

void appendHexEscape(std::string& out, const char* prefix, unsigned char c) {
  static const char* hex = "0123456789abcdef";
  out += prefix;
  out += hex[c >> 4];
  out += hex[c & 15];
}

// The length of the well-formed UTF-8 sequence at text[i] (RFC 3629: no overlong forms,
// no surrogates, nothing above U+10FFFF), or 0.
std::size_t utf8SequenceLength(std::string_view text, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char c = byte(i);
  std::size_t length = c >= 0xC2 && c <= 0xDF ? 2 : c >= 0xE0 && c <= 0xEF ? 3 : c >= 0xF0 && c <= 0xF4 ? 4 : 0;
  if (length == 0 || i + length > text.size()) return 0;
  const unsigned char second = byte(i + 1);
  const unsigned char low = c == 0xE0 ? 0xA0 : c == 0xF0 ? 0x90 : 0x80;
  const unsigned char high = c == 0xED ? 0x9F : c == 0xF4 ? 0x8F : 0xBF;
  if (second < low || second > high) return 0;
  for (std::size_t k = 2; k < length; ++k)
    if (byte(i + k) < 0x80 || byte(i + k) > 0xBF) return 0;
  return length;
}

}  // namespace

std::string quoteUserText(std::string_view text, std::size_t maxShown) {
  std::string out;
  for (std::size_t i = 0; i < text.size() && i < maxShown;) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (c < 0x80) {
      if (c < 0x20 || c == 0x7f) appendHexEscape(out, "\\x", c);
      else out += static_cast<char>(c);
      ++i;
      continue;
    }
    const std::size_t length = utf8SequenceLength(text, i);
    if (length == 0) {
      // A byte outside UTF-8: raw, 0x9B is a CSI to an 8-bit terminal.
      appendHexEscape(out, "\\x", c);
      ++i;
    } else if (c == 0xC2 && static_cast<unsigned char>(text[i + 1]) <= 0x9F) {
      // U+0080..U+009F are C1 controls: U+009B is a CSI to terminals.
      appendHexEscape(out, "\\u00", static_cast<unsigned char>(text[i + 1]));
      i += 2;
    } else {
      out.append(text.substr(i, length));
      i += length;
    }
  }
  if (text.size() > maxShown) out += "...";
  return out;
}

}  // namespace wg
