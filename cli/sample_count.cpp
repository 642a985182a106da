#include "cli/sample_count.hpp"

#include "cli/number_text.hpp"

namespace wg {

std::string setSampleCount(const std::string& value, unsigned& samples) {
  const auto count = parseCountText(value, 1, 8);
  if (!count || (*count & (*count - 1)) != 0) return "--samples takes 1 (no anti-aliasing), 2, 4 or 8";
  samples = static_cast<unsigned>(*count);
  return "";
}

}  // namespace wg
