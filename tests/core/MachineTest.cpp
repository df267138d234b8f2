// The default thread count of a run (core/Machine.h): never below one, never above the cores this
// process may use, and the whole machine when the load average leaves it idle.
#include <gtest/gtest.h>

#include "core/Machine.h"

namespace wiggle {
namespace {

TEST(Machine, IdleCoresIsTheAvailableCoresLessTheRoundedLoadAndAtLeastOne) {
  EXPECT_EQ(idleCoresOf(2, 0.0), 2);  // an idle machine: every core
  EXPECT_EQ(idleCoresOf(2, 0.4), 2);  // a load under half a core rounds away
  EXPECT_EQ(idleCoresOf(2, 0.6), 1);
  EXPECT_EQ(idleCoresOf(2, 1.5), 1);  // 1.5 rounds to 2: no core idle, but a run still gets one
  EXPECT_EQ(idleCoresOf(2, 7.0), 1);
  EXPECT_EQ(idleCoresOf(8, 2.49), 6);
  EXPECT_EQ(idleCoresOf(1, 0.0), 1);
  EXPECT_EQ(idleCoresOf(0, 0.0), 1);  // an affinity read that failed: still one thread
}

TEST(Machine, TheMachinesOwnFiguresAreSane) {
  ASSERT_GE(availableCores(), 1);
  ASSERT_GE(loadAverage(), 0.0);
  EXPECT_GE(idleCores(), 1);
  EXPECT_LE(idleCores(), availableCores());
}

}  // namespace
}  // namespace wiggle
