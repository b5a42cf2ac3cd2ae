// Stopping a driver on a signal: the handler only raises a flag (all it may safely do); the
// driver's wait loop sees it and stops its child.
#include <collido/study/stop_signals.h>

#include <csignal>

namespace collido::study {
namespace {

constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP};

std::atomic<bool> stop_requested{false};
std::atomic<int> stop_signal{0};
struct sigaction previous[sizeof kSignals / sizeof kSignals[0]];

extern "C" void raiseStop(int signal) {
  stop_signal.store(signal);
  stop_requested.store(true);
}

}  // namespace

StopOnSignals::StopOnSignals() {
  stop_requested.store(false);
  stop_signal.store(0);
  struct sigaction action {};
  action.sa_handler = raiseStop;
  sigemptyset(&action.sa_mask);
  for (std::size_t i = 0; i < sizeof kSignals / sizeof kSignals[0]; ++i)
    sigaction(kSignals[i], &action, &previous[i]);
}

StopOnSignals::~StopOnSignals() {
  for (std::size_t i = 0; i < sizeof kSignals / sizeof kSignals[0]; ++i)
    sigaction(kSignals[i], &previous[i], nullptr);
}

const std::atomic<bool>& StopOnSignals::requested() const {
  return stop_requested;
}

int StopOnSignals::signal() const {
  return stop_signal.load();
}

}  // namespace collido::study
