#include "scenario/run/RunProgress.h"

#include <gtest/gtest.h>

namespace wiggle {
namespace {

TEST(StepPace, KnowsNothingBeforeItsFirstStep) {
  const StepPace pace;
  EXPECT_EQ(pace.etaSeconds(1000), -1.0);
  EXPECT_EQ(pace.nsPerParticleStep(12000.0), 0.0);
}

// The ETA and the pace are this process's: 400 steps in 2 s leave 3 s for 600 more, and 2 s over
// 400 steps of 1,000 particles are 5,000 ns per particle-step, however long the run took before
// it was resumed (the runner gives StepPace only its own stretch: scenario/run/Experiment.cpp).
TEST(StepPace, EstimatesFromItsOwnStretch) {
  const StepPace pace{2.0, 400};
  EXPECT_DOUBLE_EQ(pace.etaSeconds(600), 3.0);
  EXPECT_DOUBLE_EQ(pace.etaSeconds(0), 0.0);
  EXPECT_DOUBLE_EQ(pace.nsPerParticleStep(1000.0), 5000.0);
}

}  // namespace
}  // namespace wiggle
