#include "cli/command_line.hpp"

namespace wg {

CommandLine::CommandLine(int argc, char** argv, int first) {
  for (int i = first; i < argc; ++i) args_.emplace_back(argv[i]);
}

std::optional<std::string> CommandLine::valueFor(const std::string& name, std::string& error) {
  if (done() || !error.empty()) return std::nullopt;
  const std::string& arg = args_[index_];
  if (arg == name) {
    if (index_ + 1 >= args_.size()) {
      error = "option '" + name + "' needs a value";
      ++index_;
      return std::nullopt;
    }
    index_ += 2;
    return args_[index_ - 1];
  }
  if (name.starts_with("--") && arg.starts_with(name + "=")) {
    ++index_;
    return arg.substr(name.size() + 1);
  }
  if (!name.starts_with("--") && name.size() == 2 && arg.size() > 2 && arg.starts_with(name)) {
    ++index_;
    return arg.substr(2);
  }
  return std::nullopt;
}

}  // namespace wg
