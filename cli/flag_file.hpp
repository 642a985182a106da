// Arguments read from a file: "--flagfile FILE" and "--flagfile=FILE" stand for FILE's
// lines, one argument each (Bazel's "multiline" parameter files, which its persistent
// workers need). A line may end in LF or CRLF, a leading UTF-8 byte-order mark is
// skipped, and an empty line is an empty argument. Not read after "--", nor inside a
// flag file.
#pragma once
#include <optional>
#include <string>
#include <vector>

namespace wg {

// `args` with each --flagfile replaced by the file's arguments; nullopt and a usage
// message naming the file when one cannot be read.
std::optional<std::vector<std::string>> expandFlagFiles(const std::vector<std::string>& args, std::string& error);

}  // namespace wg
