// `render --watch`: render, then poll the files the render read and render again
// whenever one changes, until SIGINT/SIGTERM (or a number of renders, for scripts).
// Generic over the scene source: the callback says which files it read.
#pragma once
#include <chrono>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace wg {

struct WatchedRender {
  int exitCode = 0;  // ExitCode, errors already printed
  // Every file the render read, when known (on success: the source's and the
  // materials'). Empty after a failure: the last good list stays watched.
  std::vector<std::string> inputFiles;
};

struct WatchSettings {
  std::vector<std::string> initialFiles;  // known before the first render (the graph)
  std::string output;                     // named in each render's line
  std::optional<unsigned> maxRenders;     // stop after this many, failed ones included
  std::chrono::milliseconds pollInterval{250};
  bool announce = true;  // a line on stderr saying what is watched
};

// Prints one line per render on stdout: the time, how long it took and the output (or
// that the last good output was kept). Bad input (exit 1) keeps watching; usage and
// internal errors stop. Returns the last render's exit code, or 0 when stopped by a
// signal.
int watchAndRender(const std::function<WatchedRender()>& render, const WatchSettings& settings);

}  // namespace wg
