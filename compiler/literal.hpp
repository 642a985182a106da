// JSON literals -> typed values. Numbers are float, booleans bool, arrays of 2-4
// numbers vec2-vec4.
#pragma once
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "nodes/value.hpp"

namespace wg {

struct LiteralResult {
  std::optional<Value> value;
  bool notFinite = false;  // a number that overflowed float (e.g. 1e999)
  std::string shapeError;  // why the JSON cannot be a literal; empty when fine
};

LiteralResult parseLiteral(const nlohmann::json& json);

// What kind of JSON value this is, for messages ("a string", "an array"...).
std::string describeJsonKind(const nlohmann::json& json);

// A user-supplied string made safe for a one-line message: control characters (C0,
// DEL, C1) and bytes that are not well-formed UTF-8 escaped, long text shortened.
// User text never reaches emitted code.
std::string quoteUserText(std::string_view text, std::size_t maxShown = 60);

}  // namespace wg
