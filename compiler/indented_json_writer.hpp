// JSON text written as it is built, laid out exactly as jsonText(value, 2) lays out a
// document (two-space indent, "key": value, [] and {} when empty, strings escaped
// without ensure_ascii, invalid UTF-8 replaced, C1 controls escaped): the reflection is written this way
// because building nlohmann's tree first was two thirds of a compile without SPIR-V.
#pragma once
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json_fwd.hpp>

namespace wg {

class IndentedJsonWriter {
 public:
  void beginObject();
  void endObject();
  void beginArray();
  void endArray();
  // Inside an object: the next value's key.
  IndentedJsonWriter& key(std::string_view name);
  void text(std::string_view value);
  void boolean(bool value);
  void integer(std::int64_t value);
  void number(double value);  // as nlohmann prints a double: shortest round trip, "1.0"
  void json(const nlohmann::json& value);  // any nlohmann value, objects in key order

  // The document, with the final newline the reflection files end with.
  std::string finish();

 private:
  void beforeValue();
  void open(char bracket);
  void close(char bracket);

  std::string out_;
  std::vector<bool> levelEmpty_;  // per open object or array: nothing in it yet
  bool afterKey_ = false;
};

}  // namespace wg
