#include "cli/progress_line.hpp"

#include <cstdio>

#include "compiler/literal.hpp"

namespace wg {

namespace {
constexpr std::size_t kShownNameLength = 40;
}

ProgressLine::ProgressLine(std::size_t total, bool enabled)
    : total_(total), enabled_(enabled && total > 1), start_(std::chrono::steady_clock::now()) {}

void ProgressLine::update(std::size_t done, const std::string& item) {
  if (!enabled_) return;
  double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  double eta = done > 0 ? elapsed / double(done) * double(total_ - done) : 0.0;
  std::fprintf(stderr, "\r\033[K[%zu/%zu] %s  ETA %.0fs", done, total_, quoteUserText(item, kShownNameLength).c_str(), eta);
  std::fflush(stderr);
}

void ProgressLine::finish() {
  if (!enabled_) return;
  std::fputs("\r\033[K", stderr);
  std::fflush(stderr);
}

}  // namespace wg
