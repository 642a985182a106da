#include "compiler/name_mark.hpp"

#include <cstdio>

#include "compiler/content_hash.hpp"

namespace wg {

namespace {
constexpr std::size_t kMarkDigits = 8;
}  // namespace

std::string nameMark(std::string_view name) {
  StableHasher hasher;
  hasher.add(name);
  char digits[kMarkDigits + 1];
  std::snprintf(digits, sizeof digits, "%08x", static_cast<unsigned>(hasher.value() & 0xffffffffu));
  return "h" + std::string(digits);
}

bool endsWithNameMark(std::string_view text, char separator) {
  constexpr std::size_t kSuffix = 2 + kMarkDigits;  // separator, 'h', digits
  if (text.size() < kSuffix) return false;
  std::string_view suffix = text.substr(text.size() - kSuffix);
  if (suffix[0] != separator || suffix[1] != 'h') return false;
  for (char c : suffix.substr(2))
    if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'))) return false;
  return true;
}

bool isWindowsReservedName(std::string_view stem) {
  auto upper = [](char c) { return c >= 'a' && c <= 'z' ? static_cast<char>(c - 'a' + 'A') : c; };
  std::string name;
  for (char c : stem.substr(0, stem.find('.'))) name += upper(c);
  if (name == "CON" || name == "PRN" || name == "AUX" || name == "NUL") return true;
  return name.size() == 4 && (name.starts_with("COM") || name.starts_with("LPT")) && name[3] >= '1' && name[3] <= '9';
}

}  // namespace wg
