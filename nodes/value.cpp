#include "nodes/value.hpp"

#include <charconv>
#include <cmath>

namespace wg {

Value Value::convertedTo(ValueType target) const {
  if (type == target) return *this;
  Value out{target, {}};
  for (int i = 0; i < componentCount(target); ++i) out.v[i] = at(i);
  return out;
}

bool Value::allFinite() const {
  for (int i = 0; i < width(); ++i)
    if (!std::isfinite(v[i])) return false;
  return true;
}

void appendFloat(std::string& out, float x) {
  if (x == 0.f) x = 0.f;  // folds -0 into 0 so equal constants print alike
  // Whole numbers below 10000 in magnitude, the commonest constants, as to_chars
  // spells them (its fixed form is shorter than "1e+04" up to there) but directly.
  if (std::fabs(x) < 10000.f && x == std::trunc(x)) {
    char digits[8];
    auto end = std::to_chars(digits, digits + sizeof digits, static_cast<int>(x)).ptr;
    out.append(digits, end);
    out += ".0";
    return;
  }
  char buf[64];
  auto res = std::to_chars(buf, buf + sizeof buf, x);
  std::string_view digits(buf, static_cast<std::size_t>(res.ptr - buf));
  out += digits;
  if (digits.find_first_of(".e") == std::string_view::npos) out += ".0";
}

std::string formatFloat(float x) {
  std::string s;
  appendFloat(s, x);
  return s;
}

}  // namespace wg
