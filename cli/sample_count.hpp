// --samples N, as render and bench-render take it: the most samples per pixel the lit
// pass may use (the renderer uses fewer where the device has fewer).
#pragma once
#include <string>

namespace wg {

inline constexpr unsigned kDefaultColourSamples = 4;

// "" or the usage message; `samples` is 1, 2, 4 or 8 when it succeeds.
std::string setSampleCount(const std::string& value, unsigned& samples);

}  // namespace wg
