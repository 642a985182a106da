// A one-line progress display for long batches on a terminal: count, the current
// item and an ETA, redrawn in place on stderr. Silent when disabled.
#pragma once
#include <chrono>
#include <string>

namespace wg {

class ProgressLine {
 public:
  ProgressLine(std::size_t total, bool enabled);
  void update(std::size_t done, const std::string& item);
  void finish();  // clears the line

 private:
  std::size_t total_;
  bool enabled_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace wg
