// The default thread count of a run (core/Machine.h): never below one, never above the cores this
// process may use, and the whole machine when the load average leaves it idle.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "core/Machine.h"

namespace wiggle {
namespace {

TEST(Machine, IdleCoresIsTheAvailableCoresLessTheLoadAndAtLeastOne) {
  const int cores = availableCores();
  const double load = loadAverage();
  ASSERT_GE(cores, 1);
  ASSERT_GE(load, 0.0);
  const int idle = idleCores();
  EXPECT_GE(idle, 1);
  EXPECT_LE(idle, cores);
  // The load can change between the two reads by at most a little: allow one core either way.
  const int expected = std::max(1, std::min(cores, cores - static_cast<int>(std::lround(load))));
  EXPECT_LE(std::abs(idle - expected), 1) << "load " << load << " on " << cores << " cores";
}

}  // namespace
}  // namespace wiggle
