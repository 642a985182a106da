// glslc-style argument scanning: "-o DIR", "-oDIR", "--flag value", "--flag=value",
// "-O", "-O0", "--" ends options.
#pragma once
#include <optional>
#include <string>
#include <vector>

namespace wg {

class CommandLine {
 public:
  CommandLine(int argc, char** argv, int first);
  explicit CommandLine(std::vector<std::string> args) : args_(std::move(args)) {}

  bool done() const { return index_ >= args_.size(); }
  const std::string& peek() const { return args_[index_]; }
  std::string next() { return args_[index_++]; }
  // Matches "--name value", "--name=value" and, for short names, "-nVALUE".
  // Sets error when the value is missing.
  std::optional<std::string> valueFor(const std::string& name, std::string& error);
  bool endOfOptions() const { return endOfOptions_; }
  void markEndOfOptions() { endOfOptions_ = true; }

 private:
  std::vector<std::string> args_;
  std::size_t index_ = 0;
  bool endOfOptions_ = false;
};

}  // namespace wg
