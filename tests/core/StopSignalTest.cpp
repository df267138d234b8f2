// SIGINT/SIGTERM as a stop request: seen while a guard lives, forgotten when the last one goes,
// and the handlers before the guards restored.
#include <gtest/gtest.h>

#include <atomic>
#include <csignal>

#include "core/StopSignal.h"

namespace wiggle {
namespace {

std::atomic<int> gOuterHandlerCalls{0};
extern "C" void countingHandler(int) { ++gOuterHandlerCalls; }

TEST(StopSignal, RequestSeenWhileGuardedAndForgottenAfter) {
  const auto before = std::signal(SIGTERM, countingHandler);
  EXPECT_EQ(stopSignalReceived(), 0);
  {
    const StopSignalGuard outer;
    EXPECT_EQ(stopSignalReceived(), 0);
    {
      const StopSignalGuard inner;
      std::raise(SIGINT);
      EXPECT_EQ(stopSignalReceived(), SIGINT);
    }
    EXPECT_EQ(stopSignalReceived(), SIGINT) << "an inner guard must not forget the outer one's request";
    std::raise(SIGTERM);
    EXPECT_EQ(stopSignalReceived(), SIGTERM);
  }
  EXPECT_EQ(stopSignalReceived(), 0);
  EXPECT_EQ(gOuterHandlerCalls.load(), 0);
  std::raise(SIGTERM);  // the handler from before the guards is back
  EXPECT_EQ(gOuterHandlerCalls.load(), 1);
  EXPECT_EQ(stopSignalReceived(), 0);
  std::signal(SIGTERM, before);
}

}  // namespace
}  // namespace wiggle
