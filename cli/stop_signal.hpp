// SIGINT and SIGTERM as a flag a loop polls, so `render --watch` finishes the render in
// hand and exits cleanly instead of dying mid-write.
#pragma once

namespace wg {

class StopSignal {
 public:
  StopSignal();   // installs the handlers
  ~StopSignal();  // restores the previous ones
  StopSignal(const StopSignal&) = delete;
  StopSignal& operator=(const StopSignal&) = delete;

  bool raised() const;
};

}  // namespace wg
