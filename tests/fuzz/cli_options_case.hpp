// The CLI options fuzz target's body, shared with tests/unit/fuzz_regression_test.cpp so
// that every saved input replays through exactly what the fuzzer ran.
#pragma once
#include <string>
#include <string_view>

namespace wg::fuzz {

// Splits `input` on NUL bytes into arguments and feeds them to `render`'s option
// parser (argv after "weathergen render") and, one by one, to the number, count, size,
// orbit camera and eval input (--weather, --at, --param) parsers. Returns "" or the
// property a parser broke (a value it accepted outside its own range, a number that
// does not read back, ...); crashes and sanitizer reports speak for themselves.
std::string checkCliOptionsInput(std::string_view input);

}  // namespace wg::fuzz
