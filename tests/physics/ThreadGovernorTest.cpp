// The thread governor's rule (physics/ThreadGovernor.h) on made-up windows: when it sheds a thread,
// when it tries one again, and how long it waits after a trial that failed. (That a change of thread
// count keeps the bits: WorldTest's AThreadCountChangedBetweenStepsKeepsTheBits.)
#include <gtest/gtest.h>

#include "physics/ThreadGovernor.h"

namespace wiggle {
namespace {

ThreadWindow window(double seconds, double waitShare, double idleCores = -1.0) {
  ThreadWindow w;
  w.seconds = seconds;
  w.waitShare = waitShare;
  w.idleCores = idleCores;
  return w;
}

TEST(ThreadGovernor, WaitingShareIsTheWaitOverWhatTheThreadsCanWaitAtMost) {
  StepProfile::RegionTotals regions;
  regions.threadSeconds = 2.0;  // two threads, one second of regions
  regions.waitSeconds = 1.0;    // one thread waited all through for the other
  regions.workSeconds = 1.0;
  EXPECT_DOUBLE_EQ(waitingShare(regions, 2), 1.0);
  regions.waitSeconds = 0.25;
  EXPECT_DOUBLE_EQ(waitingShare(regions, 2), 0.25);
  regions.threadSeconds = 4.0;  // four threads: three can wait at most 3 of the 4 thread-seconds
  regions.waitSeconds = 1.5;
  EXPECT_DOUBLE_EQ(waitingShare(regions, 4), 0.5);
  EXPECT_DOUBLE_EQ(waitingShare(regions, 1), 0.0);
  EXPECT_DOUBLE_EQ(waitingShare(StepProfile::RegionTotals{}, 2), 0.0);
}

TEST(ThreadGovernor, ShedsAThreadWhileTheThreadsMostlyWait) {
  ThreadRule rule;
  EXPECT_EQ(rule.next(4, 4, window(0.5, 0.3)), 4);
  EXPECT_EQ(rule.next(4, 4, window(0.5, 0.9)), 3);
  EXPECT_EQ(rule.next(3, 4, window(0.5, 0.8)), 2);
  // Two threads of a small bed on a quiet machine wait about half of what they can: they stay.
  EXPECT_EQ(rule.next(2, 4, window(0.5, 0.5)), 2);
  EXPECT_EQ(rule.next(2, 4, window(0.5, ThreadRule::kShedAbove)), 2);
  EXPECT_EQ(rule.next(2, 4, window(0.5, 0.8)), 1);
  EXPECT_EQ(rule.next(1, 4, window(0.5, 0.0, 0.0)), 1);  // never below one
}

// Seconds of windows of `seconds` each, idle as given, before the rule tries another thread.
double secondsToRetake(ThreadRule& rule, double seconds, double idleCores) {
  double waited = seconds;
  while (rule.next(1, 2, window(seconds, 0.0, idleCores)) == 1) waited += seconds;
  return waited;
}

TEST(ThreadGovernor, TakesAThreadBackSoonWhenACoreStandsIdle) {
  ThreadRule rule;
  EXPECT_EQ(rule.next(2, 2, window(0.5, 0.9)), 1);
  EXPECT_NEAR(secondsToRetake(rule, 0.5, 0.97), ThreadRule::kFirstRetry, 1e-12);
  EXPECT_EQ(rule.reason(), ThreadChangeReason::IdleCore);
  // The trial finds the threads working: they stay.
  EXPECT_EQ(rule.next(2, 2, window(0.5, 0.1, 0.0)), 2);
}

// A core held by a process of lower priority stays busy, yet the run's threads may get it: so with
// no idle core a trial comes too, later, and less often after each that fails.
TEST(ThreadGovernor, WithNoIdleCoreTriesAgainEverMoreRarely) {
  ThreadRule rule;
  EXPECT_EQ(rule.next(2, 2, window(1.0, 0.9)), 1);
  EXPECT_NEAR(secondsToRetake(rule, 1.0, 0.0), ThreadRule::kFirstRetry, 1e-12);
  EXPECT_EQ(rule.reason(), ThreadChangeReason::Trial);
  EXPECT_EQ(rule.next(2, 2, window(1.0, 0.9, 0.0)), 1);  // it failed
  EXPECT_EQ(rule.reason(), ThreadChangeReason::Waiting);
  EXPECT_NEAR(secondsToRetake(rule, 1.0, 0.0), 2 * ThreadRule::kFirstRetry, 1e-12);
  EXPECT_EQ(rule.next(2, 2, window(1.0, 0.2, 0.0)), 2);  // it held: the threads are not kept waiting
}

TEST(ThreadGovernor, IdleCoresThatMisledATrialAreNotTrustedUntilOneHolds) {
  ThreadRule rule;
  EXPECT_EQ(rule.next(2, 2, window(1.0, 0.9)), 1);
  EXPECT_NEAR(secondsToRetake(rule, 1.0, 1.0), ThreadRule::kFirstRetry, 1e-12);
  EXPECT_EQ(rule.next(2, 2, window(1.0, 0.9, 1.0)), 1);  // the idle core was not the run's to take
  EXPECT_NEAR(secondsToRetake(rule, 1.0, 1.0), 2 * ThreadRule::kFirstRetry, 1e-12);
  EXPECT_EQ(rule.next(2, 2, window(1.0, 0.1, 1.0)), 2);
  EXPECT_EQ(rule.next(2, 2, window(1.0, 0.9, 0.0)), 1);
  EXPECT_NEAR(secondsToRetake(rule, 1.0, 1.0), ThreadRule::kFirstRetry, 1e-12);  // trusted again
}

TEST(ThreadGovernor, WaitsTwiceAsLongAfterEachFailedTrialUpToTheLongest) {
  // Where the system does not say which cores are idle, the governor can only try.
  ThreadRule rule;
  EXPECT_EQ(rule.next(2, 2, window(1.0, 0.9)), 1);
  double expected = ThreadRule::kFirstRetry;
  for (int trial = 0; trial < 9; ++trial) {
    double waited = 0.0;
    while (rule.next(1, 2, window(1.0, 0.0)) == 1) waited += 1.0;
    EXPECT_NEAR(waited + 1.0, expected, 1e-12) << "trial " << trial;
    EXPECT_EQ(rule.next(2, 2, window(1.0, 0.95)), 1);  // the trial waited: back to one
    expected = std::min(2.0 * expected, ThreadRule::kLongestRetry);
  }
  EXPECT_EQ(expected, ThreadRule::kLongestRetry);
  // A trial that holds brings the retry time back to the first.
  while (rule.next(1, 2, window(1.0, 0.0)) == 1) {
  }
  EXPECT_EQ(rule.next(2, 2, window(1.0, 0.1)), 2);
  EXPECT_EQ(rule.next(2, 2, window(1.0, 0.9)), 1);
  double waited = 0.0;
  while (rule.next(1, 2, window(1.0, 0.0)) == 1) waited += 1.0;
  EXPECT_NEAR(waited + 1.0, ThreadRule::kFirstRetry, 1e-12);
}

TEST(ThreadGovernor, RetakesAsManyThreadsAsCoresStoodIdle) {
  ThreadRule rule;
  EXPECT_EQ(rule.next(8, 8, window(0.5, 0.9)), 7);
  EXPECT_EQ(rule.next(7, 8, window(0.5, 0.9)), 6);
  EXPECT_EQ(rule.next(6, 8, window(0.5, 0.9)), 5);
  EXPECT_EQ(rule.next(5, 8, window(ThreadRule::kFirstRetry, 0.1, 1.8)), 7);  // 1.8 idle cores: two more
  EXPECT_EQ(rule.next(7, 8, window(0.5, 0.1, 0.0)), 7);                       // it holds
  EXPECT_EQ(rule.next(7, 8, window(ThreadRule::kFirstRetry, 0.1, 2.9)), 8);  // three more: to the ceiling
  EXPECT_EQ(rule.next(8, 8, window(0.5, 0.1, 0.0)), 8);
}

TEST(ThreadGovernor, FollowsALowerCeiling) {
  ThreadRule rule;
  EXPECT_EQ(rule.next(4, 2, window(0.5, 0.0)), 2);
}

}  // namespace
}  // namespace wiggle
