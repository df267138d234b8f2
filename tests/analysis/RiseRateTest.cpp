#include <gtest/gtest.h>

#include <cmath>

#include "analysis/RiseRate.h"
#include "core/Error.h"

namespace wiggle {
namespace {

template <class F>
std::vector<TrajectorySample> sampled(double total, double dt, F y) {
  std::vector<TrajectorySample> s;
  for (int k = 0; k * dt <= total + 1e-9; ++k) s.push_back({k * dt, 0, y(k * dt), 0, 0, 0});
  return s;
}

TEST(RiseRate, SteadyRiseWithWiggleGivesItsSpeed) {
  // y = 10 + 0.02 t + 0.2 sin(2 pi t / 5): the paper's rule over [100, 1000] sees exactly the
  // linear part plus the wiggle's values at the two ends (both 0 at t = 100 and 1000).
  auto y = [](double t) { return 10 + 0.02 * t + 0.2 * std::sin(2 * M_PI * t / 5); };
  const RiseRate r = measureRiseRate(sampled(1000, 0.05, y), paperWindow(1000), 5, 50.0);
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
  const RiseRate shortRun = measureRiseRate(sampled(0.5, 0.05, y), paperWindow(0.5), 1, 50.0);
  EXPECT_NEAR(shortRun.windowPeriods, 0.45, 1e-9);
  EXPECT_TRUE(shortRun.windowTooShort());
  const RiseRate longRun = measureRiseRate(sampled(100, 0.05, y), paperWindow(100), 1, 50.0);
  EXPECT_NEAR(longRun.windowPeriods, 90, 1e-9);
  EXPECT_FALSE(longRun.windowTooShort());
  EXPECT_FALSE(measureRiseRate(sampled(100, 0.05, y), paperWindow(100), 45, 50.0).windowTooShort());  // 90 / 45 = 2
}

TEST(RiseRate, AWindowEndingInTheStartupTransientIsFlagged) {
  // A T = 1 run of t = 5 (4.5 periods: long enough in periods) still measures only the drive's
  // start-up transient.
  auto y = [](double t) { return 25.0 + 0.7 * t + 0.5 * std::sin(2 * M_PI * t); };
  const RiseRate early = measureRiseRate(sampled(5, 0.01, y), paperWindow(5), 1, 50.0);
  EXPECT_FALSE(early.windowTooShort());
  EXPECT_TRUE(early.withinStartupTransient());
  EXPECT_FALSE(measureRiseRate(sampled(100, 0.05, y), paperWindow(100), 5, 200.0).withinStartupTransient());
}

// A window that starts inside the transient and ends after it: warned of when more than a quarter of
// it lies in the transient (a run to t = 30: t = 3-30, 63 %), not for the presets' t = 10-100 (11 %).
TEST(RiseRate, AWindowStartingInTheStartupTransientIsFlaggedWhenMostlyInIt) {
  auto y = [](double t) { return 25.0 + 0.1 * t; };
  const RiseRate thirty = measureRiseRate(sampled(30, 0.01, y), paperWindow(30), 5, 200.0);
  EXPECT_FALSE(thirty.withinStartupTransient());
  EXPECT_NEAR(thirty.startupShare(), 17.0 / 27.0, 1e-9);
  EXPECT_TRUE(thirty.startsInStartupTransient());
  const std::vector<std::string> said = rateWarnings(thirty);
  ASSERT_EQ(said.size(), 1u);
  EXPECT_NE(said[0].find("t = 3 to 30, 63 % of it within the start-up transient"), std::string::npos) << said[0];
  EXPECT_NE(said[0].find("--from 20"), std::string::npos) << said[0];

  const RiseRate preset = measureRiseRate(sampled(100, 0.05, y), paperWindow(100), 5, 200.0);
  EXPECT_NEAR(preset.startupShare(), 10.0 / 90.0, 1e-9);
  EXPECT_FALSE(preset.startsInStartupTransient());
  EXPECT_TRUE(rateWarnings(preset).empty());
  // From t = 20 on, none of it: the measure the warning proposes.
  EXPECT_EQ(measureRiseRate(sampled(30, 0.01, y), {20.0, 30.0}, 5, 200.0).startupShare(), 0.0);
  // A window wholly inside the transient (to t = 20 included) is said once, as such, not also as
  // starting in it.
  const RiseRate twenty = measureRiseRate(sampled(20, 0.01, y), paperWindow(20), 5, 200.0);
  EXPECT_TRUE(twenty.withinStartupTransient());
  EXPECT_EQ(rateWarnings(twenty).size(), 1u);
  const RiseRate early = measureRiseRate(sampled(5, 0.01, y), paperWindow(5), 1, 50.0);
  EXPECT_TRUE(early.withinStartupTransient());
  EXPECT_FALSE(early.startsInStartupTransient());
}

TEST(RiseRate, PlateauEndsTheWindow) {
  // Rises at 0.1 until t = 400, then stays: t_f is where the plateau starts (within the averaging
  // window and tolerance: 0.5 d / 0.1 = 5 time units early at most).
  auto y = [](double t) { return 20 + 0.1 * std::min(t, 400.0); };
  const RiseRate r = measureRiseRate(sampled(1000, 0.05, y), paperWindow(1000), 2, 58.0);
  EXPECT_TRUE(r.plateau);
  EXPECT_GT(r.tFinal, 394);
  EXPECT_LE(r.tFinal, 400.5);
  EXPECT_NEAR(r.vy, 0.1, 1e-9);
  EXPECT_NEAR(r.slope, 0.1, 1e-6);
}

TEST(RiseRate, APauseInsideTheBedIsNotAPlateau) {
  // Same trajectory as above, but it stops at y = 60 while the surface is reached only at 70.
  auto y = [](double t) { return 20 + 0.1 * std::min(t, 400.0); };
  const RiseRate r = measureRiseRate(sampled(1000, 0.05, y), paperWindow(1000), 2, 70.0);
  EXPECT_FALSE(r.plateau);
  EXPECT_NEAR(r.tFinal, 1000, 1e-9);
  EXPECT_NEAR(r.vy, 30.0 / 900.0, 1e-9);
}

TEST(RiseRate, NoMotionIsNotMistakenForAPlateau) {
  auto y = [](double t) { return 30 + 0.3 * std::sin(2 * M_PI * t / 3) + 0.0001 * t; };
  const RiseRate r = measureRiseRate(sampled(100, 0.05, y), paperWindow(100), 3, 50.0);
  EXPECT_FALSE(r.plateau);
  EXPECT_NEAR(r.tFinal, 100, 1e-9);
  EXPECT_LT(std::fabs(r.vy), 0.01);
}

TEST(RiseRate, SinkingGivesNegativeRate) {
  auto y = [](double t) { return 30 - 0.01 * t; };
  const RiseRate r = measureRiseRate(sampled(200, 0.1, y), paperWindow(200), 1, 50.0);
  EXPECT_NEAR(r.vy, -0.01, 1e-12);
  EXPECT_NEAR(r.slope, -0.01, 1e-9);
}

// The paper's t_f rule (measureSettledRate): each case below is one the issue that introduced it
// named, on synthetic trajectories with the in-cycle wiggle a real intruder has.

SettledRate settledOf(const std::vector<TrajectorySample>& s, double total, double period, double surface = 1e9) {
  const RateWindow window = paperWindow(total);
  return measureSettledRate(s, window, period, measureRiseRate(s, window, period, surface));
}

double wiggle(double t, double period) { return 0.4 * std::sin(2 * M_PI * t / period); }

TEST(SettledRate, ASteadyClimbNeverSettles) {
  auto y = [](double t) { return 90 + 0.2 * t + wiggle(t, 4); };
  const auto s = sampled(1000, 0.05, y);
  const SettledRate r = settledOf(s, 1000, 4);
  EXPECT_FALSE(r.settled);
  EXPECT_EQ(r.tSettled, 1000);
  EXPECT_EQ(r.vy, measureRiseRate(s, paperWindow(1000), 4, 1e9).vy);  // vy_settled == vy, to the bit
}

TEST(SettledRate, AClimbThatStopsEndsTheWindowWhereItStops) {
  // Climbs at 0.05 from t = 0 to 250 (12.5 d), then stays: t_f is where the averaged height comes
  // within the band (1 d) of the final level, i.e. about 1 / 0.05 = 20 before the stop, give or
  // take the averaging window (12 at T = 3).
  auto y = [](double t) { return 90 + 0.05 * std::min(t, 250.0) + wiggle(t, 3); };
  const SettledRate r = settledOf(sampled(1000, 0.05, y), 1000, 3);
  EXPECT_TRUE(r.settled);
  EXPECT_GT(r.tSettled, 250 - 20 - 6);
  EXPECT_LE(r.tSettled, 250);
  EXPECT_NEAR(r.vy, 0.05, 0.8 / (r.tSettled - 100));  // the chord's ends carry the wiggle (+-0.4 d)
}

TEST(SettledRate, ASinkThatStopsSettlesToo) {
  auto y = [](double t) { return 90 - 0.1 * std::min(t, 500.0) + wiggle(t, 2); };
  const SettledRate r = settledOf(sampled(1000, 0.05, y), 1000, 2);
  EXPECT_TRUE(r.settled);
  EXPECT_GT(r.tSettled, 500 - 10 - 6);
  EXPECT_LE(r.tSettled, 500);
  EXPECT_NEAR(r.vy, -0.1, 0.8 / (r.tSettled - 100));
}

TEST(SettledRate, NoiseAroundAPlateauIsNotASettling) {
  // An intruder that stays where it is, with slow fluctuations of +-1.8 d (a bed's) that calm to
  // +-0.5 d from t = 400: the calm stretch is long and flat, but the intruder never went anywhere
  // (less than 4 bands from where it was at t_i), so it never "reached" a final position.
  auto y = [](double t) { return 90 + (t < 400 ? 1.8 : 0.5) * std::sin(t / 15) + wiggle(t, 3); };
  const auto s = sampled(1000, 0.05, y);
  const SettledRate r = settledOf(s, 1000, 3);
  EXPECT_FALSE(r.settled);
  EXPECT_EQ(r.vy, measureRiseRate(s, paperWindow(1000), 3, 1e9).vy);
}

TEST(SettledRate, ReachingTheSurfaceSettlesWhereTheRunsPlateauRuleDoes) {
  // The run's own rule moves t_f to the plateau at the surface; the settle rule agrees within the
  // two rules' tolerances (0.5 d and 1 d over a rate of 0.1 d per time unit: 10 time units).
  auto y = [](double t) { return 20 + 0.1 * std::min(t, 400.0) + wiggle(t, 2); };
  const auto s = sampled(1000, 0.05, y);
  const RateWindow window = paperWindow(1000);
  const RiseRate own = measureRiseRate(s, window, 2, 58.0);
  const SettledRate r = measureSettledRate(s, window, 2, own);
  ASSERT_TRUE(own.plateau);
  EXPECT_TRUE(r.settled);
  EXPECT_NEAR(r.tSettled, own.tFinal, 10);
  EXPECT_NEAR(r.vy, 0.1, 0.002);
}

TEST(SettledRate, AStartUpTransientIsNotAnApproach) {
  // Drops 10 d within 3 time units after t_i = 10 of a t = 100 run, then stays: the approach is
  // shorter than 10 % of the window, so the whole window is the rate's.
  auto y = [](double t) { return 25 - 10 * std::min(std::max(t - 10, 0.0), 3.0) / 3 + wiggle(t, 1); };
  EXPECT_FALSE(settledOf(sampled(100, 0.05, y), 100, 1).settled);
}

TEST(SettledRate, ASlowSteadyClimbIsNotAPlateau) {
  // At 0.01 d per time unit the last 200 time units stay within 1 d of their mean: long enough,
  // after a long enough approach of 8 d; but the "plateau" climbs as fast as the approach.
  auto y = [](double t) { return 90 + 0.01 * t + wiggle(t, 5); };
  EXPECT_FALSE(settledOf(sampled(1000, 0.05, y), 1000, 5).settled);
}

TEST(SettledRate, TheBandIsTheRulesOneParameter) {
  // The climb that stops, read with a band wider than its travel / 4: nothing settles.
  auto y = [](double t) { return 90 + 0.05 * std::min(t, 250.0) + wiggle(t, 3); };
  const auto s = sampled(1000, 0.05, y);
  const RateWindow window = paperWindow(1000);
  const RiseRate own = measureRiseRate(s, window, 3, 1e9);
  SettleRule wide;
  wide.band = 4.0;  // 4 bands = 16 d > the 12.5 d climbed
  EXPECT_FALSE(measureSettledRate(s, window, 3, own, wide).settled);
  SettleRule narrow;
  narrow.band = 0.5;
  const SettledRate r = measureSettledRate(s, window, 3, own, narrow);
  EXPECT_TRUE(r.settled);
  EXPECT_GT(r.tSettled, 250 - 10 - 6);
  SettleRule zero;
  zero.band = 0.0;
  EXPECT_THROW(measureSettledRate(s, window, 3, own, zero), Error);
}

TEST(SettleRule, SmoothsOverWholePeriodsOfAtLeastTenTimeUnits) {
  const SettleRule rule;
  EXPECT_DOUBLE_EQ(rule.smoothing(2.5), 10.0);
  EXPECT_DOUBLE_EQ(rule.smoothing(3.0), 12.0);
  EXPECT_DOUBLE_EQ(rule.smoothing(0.5), 10.0);
  EXPECT_DOUBLE_EQ(rule.smoothing(8.0), 16.0);
  EXPECT_DOUBLE_EQ(rule.smoothing(12.0), 12.0);
}

TEST(RateWindow, ARunReadToAnEarlierTimeIsTheShorterRun) {
  // The data after `to` is ignored: a t = 1000 trajectory read to 100 gives the t = 100 run's rate.
  auto y = [](double t) { return 90 + 0.02 * t + 0.3 * std::sin(t / 7) + wiggle(t, 3); };
  const auto longRun = sampled(1000, 0.05, y), shortRun = sampled(100, 0.05, y);
  const RiseRate a = measureRiseRate(longRun, {10, 100}, 3, 1e9),
                 b = measureRiseRate(shortRun, paperWindow(100), 3, 1e9);
  EXPECT_EQ(a.vy, b.vy);
  EXPECT_EQ(a.slope, b.slope);
  EXPECT_EQ(a.tFinal, 100);
  const RiseRate c = measureRiseRate(longRun, {100, 1000}, 3, 1e9);
  EXPECT_EQ(c.tInitial, 100);
  EXPECT_EQ(c.vy, (y(1000) - y(100)) / 900);
  EXPECT_THROW(measureRiseRate(longRun, {500, 400}, 3, 1e9), Error);
}

}  // namespace
}  // namespace wiggle
