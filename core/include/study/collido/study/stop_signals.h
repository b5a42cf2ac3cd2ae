#pragma once

#include <atomic>

namespace collido::study {

/// While one is alive, SIGINT (Ctrl-C), SIGTERM and SIGHUP (a dropped ssh session) do not end the
/// process: they raise `requested()`, which a driver passes to runWorkerProcess as its `stop`, so
/// the running child and everything it started are killed and the driver leaves its folder
/// consistent before it exits. The previous handlers come back when it is destroyed. One at a
/// time per process.
class StopOnSignals {
 public:
  StopOnSignals();
  ~StopOnSignals();
  StopOnSignals(const StopOnSignals&) = delete;
  StopOnSignals& operator=(const StopOnSignals&) = delete;

  /// Becomes true at the first of the signals.
  const std::atomic<bool>& requested() const;
  /// The signal that asked to stop (0 while none has).
  int signal() const;
};

}  // namespace collido::study
