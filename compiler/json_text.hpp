// JSON text as weathergen writes it for people and tools: nlohmann's dump without
// ensure_ascii (names stay readable), invalid UTF-8 replaced by U+FFFD, and the C1
// controls U+0080..U+009F escaped, since U+009B is a CSI to a terminal showing the file.
#pragma once
#include <string>

#include <nlohmann/json.hpp>

namespace wg {

// indent as nlohmann's dump takes it: -1 for one line.
std::string jsonText(const nlohmann::json& value, int indent = -1);
std::string jsonText(const nlohmann::ordered_json& value, int indent = -1);

// Dumped JSON text with each C1 control written as \u00XX. In valid UTF-8 its two bytes
// (C2 80..9F) encode nothing else, and JSON holds them only inside strings.
std::string escapeC1Controls(std::string text);

}  // namespace wg
