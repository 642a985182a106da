// What the bench commands share on their command line: --frames N, and reading their
// option table with their one-line usage errors.
#pragma once
#include <optional>
#include <string>

#include "cli/option_table.hpp"

namespace wg {

// "" or the usage message; `frames` is 1 to 1000000 when it succeeds.
std::string setFrameCount(const std::string& value, int& frames);

// Reads argv into the table's setters. The exit code when the command is done: a usage
// error (printed), or `help` set by the table and `usage` printed.
std::optional<int> parseBenchOptions(const OptionTable& table, int argc, char** argv, const bool& help,
                                     const char* usage);

}  // namespace wg
