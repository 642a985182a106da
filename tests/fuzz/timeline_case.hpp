// The timeline fuzz target's body, shared with tests/unit/fuzz_regression_test.cpp so
// that every saved input replays through exactly what the fuzzer ran.
#pragma once
#include <string>
#include <string_view>

namespace wg::fuzz {

// Reads `input` as `render --timeline` does (parseJsonDocument, then
// parseWeatherTimeline, locating its error in the document), samples the timeline and
// simulates along it in at most a few hundred steps. Returns "" or the property broken
// (an accepted timeline that fails validate(), conditions or states out of range, time
// going backwards, ...); crashes and sanitizer reports speak for themselves.
std::string checkTimelineInput(std::string_view input);

}  // namespace wg::fuzz
