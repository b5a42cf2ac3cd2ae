// Drivers stop on SIGINT, SIGTERM and SIGHUP by raising a flag, and give the signals back after.
#include <collido/study/stop_signals.h>

#include <csignal>

#include <gtest/gtest.h>

namespace collido::study {
namespace {

TEST(StopOnSignals, EachSignalRaisesTheFlagAndTheHandlersComeBack) {
  for (const int signal : {SIGINT, SIGTERM, SIGHUP}) {
    struct sigaction before {};
    sigaction(signal, nullptr, &before);  // SIG_DFL, or SIG_IGN under nohup
    {
      const StopOnSignals stop;
      EXPECT_FALSE(stop.requested().load());
      ASSERT_EQ(std::raise(signal), 0);
      EXPECT_TRUE(stop.requested().load()) << signal;
      EXPECT_EQ(stop.signal(), signal);
    }
    struct sigaction now {};
    sigaction(signal, nullptr, &now);
    EXPECT_EQ(now.sa_handler, before.sa_handler) << signal;
  }
}

}  // namespace
}  // namespace collido::study
