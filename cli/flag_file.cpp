#include "cli/flag_file.hpp"

#include "compiler/literal.hpp"
#include "nodes/regular_file.hpp"

namespace wg {

namespace {

// Far above any command line: a material's arguments are a few hundred bytes.
constexpr std::uintmax_t kMaxFlagFileBytes = 1u << 20;

bool readFlagFile(const std::string& path, std::vector<std::string>& args, std::string& error) {
  std::string text;
  const FileRead read = readRegularFile(path, kMaxFlagFileBytes, text);
  if (read.status == FileReadStatus::TooLarge) {
    error = "--flagfile '" + quoteUserText(path) + "' is larger than " + std::to_string(kMaxFlagFileBytes) + " bytes";
    return false;
  }
  if (read.status != FileReadStatus::Ok) {
    error = "--flagfile '" + quoteUserText(path) + "': " + read.reason;
    return false;
  }
  if (text.find('\0') != std::string::npos) {
    error = "--flagfile '" + quoteUserText(path) + "' holds a NUL character; it must be text, one argument a line";
    return false;
  }
  // A byte-order mark some editors write: it would start the first argument.
  if (text.starts_with("\xEF\xBB\xBF")) text.erase(0, 3);
  if (!text.empty() && text.back() == '\n') text.pop_back();  // the last line's end
  if (text.empty()) return true;
  std::size_t start = 0;
  for (;;) {
    const std::size_t end = text.find('\n', start);
    std::string line = text.substr(start, end - start);
    // A CRLF line end written by hand: a trailing CR would end up in a path or option.
    if (!line.empty() && line.back() == '\r') line.pop_back();
    args.push_back(std::move(line));
    if (end == std::string::npos) return true;
    start = end + 1;
  }
}

}  // namespace

std::optional<std::vector<std::string>> expandFlagFiles(const std::vector<std::string>& args, std::string& error) {
  std::vector<std::string> expanded;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if (arg == "--") {
      expanded.insert(expanded.end(), args.begin() + static_cast<std::ptrdiff_t>(i), args.end());
      break;
    }
    std::optional<std::string> path;
    if (arg.starts_with("--flagfile=")) path = arg.substr(11);
    else if (arg == "--flagfile") {
      if (i + 1 == args.size()) {
        error = "option '--flagfile' needs a value";
        return std::nullopt;
      }
      path = args[++i];
    }
    if (path && path->empty()) {
      error = "--flagfile takes a file name (it is empty; is a build variable unset?)";
      return std::nullopt;
    }
    if (!path) expanded.push_back(arg);
    else if (!readFlagFile(*path, expanded, error)) return std::nullopt;
  }
  return expanded;
}

}  // namespace wg
