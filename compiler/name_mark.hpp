// A short mark of a name's exact bytes, appended where making the name safe (for a file
// or a C++ identifier) changed it. Distinct names then map to distinct safe names across
// runs: '雪' and '雨' both sanitise to '_' but keep their own marks.
#pragma once
#include <string>
#include <string_view>

namespace wg {

// "h" and 8 hex digits of the name's 64-bit FNV-1a hash: "h3f2a9c1b".
std::string nameMark(std::string_view name);

// Whether `text` ends with `separator` followed by a mark, as a marked name does. A name
// that already looks marked is marked again, so no verbatim name equals a marked one.
bool endsWithNameMark(std::string_view text, char separator);

// Whether Windows reserves `stem` as a file name, whatever the case and the extension:
// CON, PRN, AUX, NUL, COM1-COM9, LPT1-LPT9. Such a stem is marked like any unsafe name.
bool isWindowsReservedName(std::string_view stem);

}  // namespace wg
