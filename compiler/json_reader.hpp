// A fast front end to nlohmann's SAX interface: RapidJSON's reader scans the text and
// sends the events nlohmann's own lexer would, value for value. nlohmann's lexer
// costs about 75 instructions a byte; a graph's parse was a fifth of a compile.
#pragma once
#include <string>

#include <nlohmann/json.hpp>

namespace wg {

// nlohmann's own DOM builder, also counting the keys it is given: nlohmann keeps only
// the last of two equal keys, silently, so a document whose objects hold fewer members
// than the keys read has a duplicate. Either reader sends it the same events.
class JsonDomBuilder final : public nlohmann::json::json_sax_t {
 public:
  explicit JsonDomBuilder(nlohmann::json& root) : dom_(root, /*allow_exceptions=*/true) {}
  bool null() override { return dom_.null(); }
  bool boolean(bool value) override { return dom_.boolean(value); }
  bool number_integer(number_integer_t value) override { return dom_.number_integer(value); }
  bool number_unsigned(number_unsigned_t value) override { return dom_.number_unsigned(value); }
  bool number_float(number_float_t value, const string_t& text) override { return dom_.number_float(value, text); }
  bool string(string_t& value) override { return dom_.string(value); }
  bool binary(binary_t& value) override { return dom_.binary(value); }
  bool start_object(std::size_t size) override { return dom_.start_object(size); }
  bool key(string_t& value) override {
    ++keys_;
    return dom_.key(value);
  }
  bool end_object() override { return dom_.end_object(); }
  bool start_array(std::size_t size) override { return dom_.start_array(size); }
  bool end_array() override { return dom_.end_array(); }
  // Throws nlohmann's error as its own type (it arrives by its base class).
  bool parse_error(std::size_t position, const std::string& token, const nlohmann::detail::exception& e) override;
  std::size_t keysRead() const { return keys_; }
  // After an error: the byte where its token starts, and the token.
  std::size_t errorTokenStart() const { return errorEnd_ > errorToken_.size() ? errorEnd_ - errorToken_.size() : 0; }
  const std::string& errorToken() const { return errorToken_; }

 private:
  nlohmann::detail::json_sax_dom_parser<nlohmann::json> dom_;
  std::size_t keys_ = 0;
  std::size_t errorEnd_ = 0;
  std::string errorToken_;
};

// True when the whole text was read and every event sent. False on anything it does
// not reproduce exactly (a syntax error, a number out of double's range, an encoded
// surrogate, a byte-order mark) and on nesting deeper than maxDepth: the caller then
// parses with nlohmann alone, whose errors name what is wrong. Events may have been
// sent before a false. The text must not hold a NUL.
bool readJsonEvents(const std::string& text, nlohmann::json::json_sax_t& events, int maxDepth = 64);

}  // namespace wg
