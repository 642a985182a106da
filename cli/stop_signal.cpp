#include "cli/stop_signal.hpp"

#include <csignal>

namespace wg {

namespace {
volatile std::sig_atomic_t stopRequested = 0;
struct sigaction previousInt, previousTerm;

void requestStop(int) { stopRequested = 1; }
}  // namespace

StopSignal::StopSignal() {
  stopRequested = 0;
  struct sigaction action {};
  action.sa_handler = requestStop;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, &previousInt);
  sigaction(SIGTERM, &action, &previousTerm);
}

StopSignal::~StopSignal() {
  sigaction(SIGINT, &previousInt, nullptr);
  sigaction(SIGTERM, &previousTerm, nullptr);
}

bool StopSignal::raised() const { return stopRequested != 0; }

}  // namespace wg
