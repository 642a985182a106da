#include "compiler/json_reader.hpp"

#include <charconv>
#include <cstdint>
#include <stdexcept>

// x86-64 always has SSE2: RapidJSON then scans strings and white space 16 bytes at a time.
#if defined(__SSE2__) && !defined(RAPIDJSON_SSE2)
#define RAPIDJSON_SSE2
#endif
#include <rapidjson/reader.h>

namespace wg {

namespace {

// A number as nlohmann's lexer classifies it: with a fraction or an exponent a
// double, else an int64 when signed and a uint64 when not, and an integer too large
// for its type a double as well.
bool sendNumber(const char* text, std::size_t length, nlohmann::json::json_sax_t& events) {
  const char* end = text + length;
  bool fractional = false;
  for (const char* c = text; c != end; ++c) fractional = fractional || *c == '.' || *c == 'e' || *c == 'E';
  if (!fractional) {
    if (text[0] == '-') {
      std::int64_t value;
      auto [at, error] = std::from_chars(text, end, value);
      if (error == std::errc() && at == end) return events.number_integer(value);
    } else {
      std::uint64_t value;
      auto [at, error] = std::from_chars(text, end, value);
      if (error == std::errc() && at == end) return events.number_unsigned(value);
    }
  }
  double value;
  auto [at, error] = std::from_chars(text, end, value);
  // Out of range (overflow, or underflow that strtod would round): left to nlohmann.
  if (error != std::errc() || at != end) return false;
  std::string raw(text, length);
  return events.number_float(value, raw);
}

// RapidJSON decodes a lone \uDC00-\uDFFF escape to its 3-byte form; nlohmann refuses it.
bool holdsEncodedSurrogate(const char* text, std::size_t length) {
  for (std::size_t i = 0; i + 1 < length; ++i)
    if (static_cast<unsigned char>(text[i]) == 0xED && static_cast<unsigned char>(text[i + 1]) >= 0xA0) return true;
  return false;
}

class EventForwarder : public rapidjson::BaseReaderHandler<rapidjson::UTF8<>, EventForwarder> {
 public:
  EventForwarder(nlohmann::json::json_sax_t& events, int maxDepth) : events_(events), maxDepth_(maxDepth) {}
  bool Null() { return events_.null(); }
  bool Bool(bool value) { return events_.boolean(value); }
  bool RawNumber(const char* text, rapidjson::SizeType length, bool) { return sendNumber(text, length, events_); }
  bool String(const char* text, rapidjson::SizeType length, bool) {
    if (holdsEncodedSurrogate(text, length)) return false;
    std::string value(text, length);
    return events_.string(value);
  }
  bool Key(const char* text, rapidjson::SizeType length, bool) {
    if (holdsEncodedSurrogate(text, length)) return false;
    std::string value(text, length);
    return events_.key(value);
  }
  bool StartObject() { return ++depth_ <= maxDepth_ && events_.start_object(static_cast<std::size_t>(-1)); }
  bool EndObject(rapidjson::SizeType) { return --depth_, events_.end_object(); }
  bool StartArray() { return ++depth_ <= maxDepth_ && events_.start_array(static_cast<std::size_t>(-1)); }
  bool EndArray(rapidjson::SizeType) { return --depth_, events_.end_array(); }

 private:
  nlohmann::json::json_sax_t& events_;
  int maxDepth_;
  int depth_ = 0;
};

}  // namespace

bool JsonDomBuilder::parse_error(std::size_t position, const std::string& token, const nlohmann::detail::exception& e) {
  errorEnd_ = position;
  errorToken_ = token;
  if (const auto* syntax = dynamic_cast<const nlohmann::json::parse_error*>(&e)) throw *syntax;
  if (const auto* range = dynamic_cast<const nlohmann::json::out_of_range*>(&e)) throw *range;
  throw std::runtime_error(e.what());
}

namespace {
// ASCII text needs no encoding check, and RapidJSON only takes its SIMD string scan
// without one.
bool isAscii(const std::string& text) {
  unsigned char bits = 0;
  for (unsigned char c : text) bits |= c;
  return bits < 0x80;
}

template <unsigned Flags>
bool parse(const std::string& text, nlohmann::json::json_sax_t& events, int maxDepth) {
  // The SIMD scan reads whole aligned 16-byte blocks, so the block holding the final
  // NUL may reach past the text's allocation: pad it. The caller has refused text
  // holding a NUL, so the C string ends where the text does.
  // The copy is read in place (RapidJSON decodes each string where it lies instead of
  // copying it to a buffer of its own first).
  std::string padded;
  padded.reserve(text.size() + 16);
  padded = text;
  padded.append(15, '\0');
  rapidjson::InsituStringStream stream(padded.data());
  rapidjson::Reader reader;
  EventForwarder forwarder(events, maxDepth);
  return !reader.Parse<Flags | rapidjson::kParseInsituFlag>(stream, forwarder).IsError();
}
}  // namespace

bool readJsonEvents(const std::string& text, nlohmann::json::json_sax_t& events, int maxDepth) {
  // nlohmann skips a UTF-8 byte-order mark; RapidJSON would call it a syntax error.
  if (text.starts_with("\xEF\xBB\xBF")) return false;
  constexpr unsigned kFlags = rapidjson::kParseIterativeFlag | rapidjson::kParseNumbersAsStringsFlag;
  if (isAscii(text)) return parse<kFlags>(text, events, maxDepth);
  return parse<kFlags | rapidjson::kParseValidateEncodingFlag>(text, events, maxDepth);
}

}  // namespace wg
