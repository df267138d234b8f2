#include <gtest/gtest.h>

#include <cmath>

#include "analysis/RiseRate.h"

namespace wiggle {
namespace {

std::vector<TrajectorySample> sampled(double total, double dt, double (*y)(double)) {
  std::vector<TrajectorySample> s;
  for (int k = 0; k * dt <= total + 1e-9; ++k) s.push_back({k * dt, 0, y(k * dt), 0, 0, 0});
  return s;
}

TEST(RiseRate, SteadyRiseWithWiggleGivesItsSpeed) {
  // y = 10 + 0.02 t + 0.2 sin(2 pi t / 5): the paper's rule over [100, 1000] sees exactly the
  // linear part plus the wiggle's values at the two ends (both 0 at t = 100 and 1000).
  auto y = [](double t) { return 10 + 0.02 * t + 0.2 * std::sin(2 * M_PI * t / 5); };
  const RiseRate r = measureRiseRate(sampled(1000, 0.05, y), 1000, 5, 50.0);
  EXPECT_FALSE(r.plateau);
  EXPECT_NEAR(r.tInitial, 100, 1e-9);
  EXPECT_NEAR(r.tFinal, 1000, 1e-9);
  EXPECT_NEAR(r.vy, 0.02, 1e-9);
  EXPECT_NEAR(r.slope, 0.02, 1e-5);
}

TEST(RiseRate, AWindowOfFewerThanTwoPeriodsIsFlagged) {
  // A resting intruder wiggling at T = 1 and sampled over t = 0.5: the window [0.05, 0.5] is 0.45
  // periods, and its chord reads the swing (here 0.2 sin(2 pi t)) as a rate of 0.4. Over t = 100 the
  // same motion gives 90 periods and no flag; exactly 2 periods is enough.
  auto y = [](double t) { return 25 + 0.2 * std::sin(2 * M_PI * t); };
  const RiseRate shortRun = measureRiseRate(sampled(0.5, 0.05, y), 0.5, 1, 50.0);
  EXPECT_NEAR(shortRun.windowPeriods, 0.45, 1e-9);
  EXPECT_TRUE(shortRun.windowTooShort());
  const RiseRate longRun = measureRiseRate(sampled(100, 0.05, y), 100, 1, 50.0);
  EXPECT_NEAR(longRun.windowPeriods, 90, 1e-9);
  EXPECT_FALSE(longRun.windowTooShort());
  EXPECT_FALSE(measureRiseRate(sampled(100, 0.05, y), 100, 45, 50.0).windowTooShort());  // 90 / 45 = 2
}

TEST(RiseRate, AWindowEndingInTheStartupTransientIsFlagged) {
  // A T = 1 run of t = 5 (4.5 periods: long enough in periods) still measures only the drive's
  // start-up transient.
  auto y = [](double t) { return 25.0 + 0.7 * t + 0.5 * std::sin(2 * M_PI * t); };
  const RiseRate early = measureRiseRate(sampled(5, 0.01, y), 5, 1, 50.0);
  EXPECT_FALSE(early.windowTooShort());
  EXPECT_TRUE(early.withinStartupTransient());
  EXPECT_FALSE(measureRiseRate(sampled(100, 0.05, y), 100, 5, 200.0).withinStartupTransient());
}

TEST(RiseRate, PlateauEndsTheWindow) {
  // Rises at 0.1 until t = 400, then stays: t_f is where the plateau starts (within the averaging
  // window and tolerance: 0.5 d / 0.1 = 5 time units early at most).
  auto y = [](double t) { return 20 + 0.1 * std::min(t, 400.0); };
  const RiseRate r = measureRiseRate(sampled(1000, 0.05, y), 1000, 2, 58.0);
  EXPECT_TRUE(r.plateau);
  EXPECT_GT(r.tFinal, 394);
  EXPECT_LE(r.tFinal, 400.5);
  EXPECT_NEAR(r.vy, 0.1, 1e-9);
  EXPECT_NEAR(r.slope, 0.1, 1e-6);
}

TEST(RiseRate, APauseInsideTheBedIsNotAPlateau) {
  // Same trajectory as above, but it stops at y = 60 while the surface is reached only at 70.
  auto y = [](double t) { return 20 + 0.1 * std::min(t, 400.0); };
  const RiseRate r = measureRiseRate(sampled(1000, 0.05, y), 1000, 2, 70.0);
  EXPECT_FALSE(r.plateau);
  EXPECT_NEAR(r.tFinal, 1000, 1e-9);
  EXPECT_NEAR(r.vy, 30.0 / 900.0, 1e-9);
}

TEST(RiseRate, NoMotionIsNotMistakenForAPlateau) {
  auto y = [](double t) { return 30 + 0.3 * std::sin(2 * M_PI * t / 3) + 0.0001 * t; };
  const RiseRate r = measureRiseRate(sampled(100, 0.05, y), 100, 3, 50.0);
  EXPECT_FALSE(r.plateau);
  EXPECT_NEAR(r.tFinal, 100, 1e-9);
  EXPECT_LT(std::fabs(r.vy), 0.01);
}

TEST(RiseRate, SinkingGivesNegativeRate) {
  auto y = [](double t) { return 30 - 0.01 * t; };
  const RiseRate r = measureRiseRate(sampled(200, 0.1, y), 200, 1, 50.0);
  EXPECT_NEAR(r.vy, -0.01, 1e-12);
  EXPECT_NEAR(r.slope, -0.01, 1e-9);
}

}  // namespace
}  // namespace wiggle
