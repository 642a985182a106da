#include "cli/render_watch.hpp"

#include <cstdio>
#include <ctime>
#include <thread>

#include "cli/commands.hpp"
#include "cli/file_stamps.hpp"
#include "cli/stop_signal.hpp"
#include "compiler/literal.hpp"

namespace wg {

namespace {

std::string clockTime() {
  std::time_t now = std::time(nullptr);
  std::tm local{};
  localtime_r(&now, &local);
  char text[16];
  std::strftime(text, sizeof text, "%H:%M:%S", &local);
  return text;
}

void printRenderLine(const WatchedRender& result, double milliseconds, const std::string& output, bool earlierGood) {
  const std::string now = clockTime(), quoted = quoteUserText(output, 300);
  const char *at = now.c_str(), *out = quoted.c_str();
  if (result.exitCode == kExitOk) std::printf("%s  rendered %s in %.0f ms\n", at, out, milliseconds);
  else if (earlierGood) std::printf("%s  failed after %.0f ms; kept the last good %s\n", at, milliseconds, out);
  else std::printf("%s  failed after %.0f ms; nothing written to %s yet\n", at, milliseconds, out);
  std::fflush(stdout);
}

// Sleeps until a watched file changes or a stop is asked for; false on a stop.
bool waitForChange(const FileStamps& stamps, const StopSignal& stop, std::chrono::milliseconds interval) {
  constexpr auto kSlice = std::chrono::milliseconds(50);  // how soon a signal is noticed
  while (!stop.raised()) {
    for (auto slept = std::chrono::milliseconds(0); slept < interval && !stop.raised(); slept += kSlice)
      std::this_thread::sleep_for(kSlice);
    if (!stop.raised() && !stamps.firstChanged().empty()) return true;
  }
  return false;
}

}  // namespace

int watchAndRender(const std::function<WatchedRender()>& render, const WatchSettings& settings) {
  StopSignal stop;
  std::vector<std::string> watched = settings.initialFiles;
  bool announced = !settings.announce, anyGood = false;
  for (unsigned renders = 1;; ++renders) {
    FileStamps stamps(watched);  // before the render: an edit during it counts
    auto start = std::chrono::steady_clock::now();
    WatchedRender result = render();
    double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    printRenderLine(result, ms, settings.output, anyGood);
    anyGood = anyGood || result.exitCode == kExitOk;
    if (result.exitCode != kExitOk && result.exitCode != kExitBadInput) return result.exitCode;
    if (result.exitCode == kExitOk && !result.inputFiles.empty()) {
      watched = result.inputFiles;
      stamps = FileStamps(watched, stamps);
      if (!announced) std::fprintf(stderr, "watch: %zu files; Ctrl-C stops\n", watched.size());
      announced = true;
    }
    if (settings.maxRenders && renders >= *settings.maxRenders) return result.exitCode;
    if (!waitForChange(stamps, stop, settings.pollInterval)) return kExitOk;
  }
}

}  // namespace wg
