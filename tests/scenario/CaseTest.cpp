// The checked case (scenario/case/Case.h): every number a run derives from its config, worked out once,
// and the drive's one formula.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/Error.h"
#include "io/Config.h"
#include "scenario/case/Case.h"

namespace wiggle {
namespace {

TEST(Case, DerivesTheScheduleInSteps) {
  RunConfig config;  // dt = 1e-4
  config.run.duration = 2.0;
  config.run.sampleInterval = 0.05;
  config.run.dumpInterval = 0.3;
  config.drive.period = 0.4;
  config.fields.phases = {0, 5, 10, 19};
  validateRunConfig(config);
  const Case c = prepareCase(config);
  EXPECT_EQ(c.steps.total, 20000u);
  EXPECT_EQ(c.steps.sampleEvery, 500u);
  EXPECT_EQ(c.steps.dumpEvery, 3000u);
  EXPECT_EQ(c.steps.period, 4000u);
  EXPECT_EQ(c.steps.firstMeasured, 2000u);  // 0.1 of the run
  // 10 phi / pi = p is p / 20 of a period: 0, a quarter, a half, 19/20.
  EXPECT_EQ(c.steps.fieldPhaseStep, (std::vector<std::uint64_t>{0, 1000, 2000, 3800}));
  config.run.dumpInterval = 0.0;
  EXPECT_EQ(prepareCase(config).steps.dumpEvery, 0u);
}

TEST(Case, DriveIsTheSinusoidAboutTheBoxCentre) {
  RunConfig config;
  config.drive.amplitude = 3.0;
  config.drive.period = 2.0;
  const Case c = prepareCase(config);
  EXPECT_EQ(c.drive.kind, HorizontalMotion::Sinusoid);
  EXPECT_TRUE(c.drive.verticalFree);
  const double x0 = 0.5 * config.box.width, w = std::numbers::pi;  // 2 pi / T
  for (double t : {0.0, 0.3, 0.5, 1.7}) {
    EXPECT_DOUBLE_EQ(c.drive.at(t).x, x0 + 3.0 * std::sin(w * t)) << t;
    EXPECT_DOUBLE_EQ(c.drive.at(t).vx, 3.0 * w * std::cos(w * t)) << t;
  }
  config.drive.rampPeriods = 2;
  const Case ramped = prepareCase(config);
  EXPECT_EQ(ramped.drive.kind, HorizontalMotion::RampedSinusoid);
  EXPECT_DOUBLE_EQ(ramped.drive.rampTime, 4.0);
  EXPECT_DOUBLE_EQ(ramped.drive.at(1.5).x, x0 + 3.0 * (1.5 / 4.0) * std::sin(w * 1.5));
  EXPECT_DOUBLE_EQ(ramped.drive.at(4.5).x, x0 + 3.0 * std::sin(w * 4.5));  // past the ramp: the plain drive
}

// drive.form = "velocity": the paper's formula read as a velocity (docs/PHYSICS.md §7).
TEST(Case, VelocityFormDrivesVxAsTheSinusoidFromRest) {
  RunConfig config;
  config.drive.amplitude = 3.0;
  config.drive.period = 2.0;
  config.drive.form = DriveForm::Velocity;
  const Case c = prepareCase(config);
  EXPECT_EQ(c.drive.kind, HorizontalMotion::VelocitySinusoid);
  const double x0 = 0.5 * config.box.width, w = std::numbers::pi;
  for (double t : {0.0, 0.3, 0.5, 1.0, 1.7}) {
    EXPECT_DOUBLE_EQ(c.drive.at(t).x, x0 + 3.0 / w * (1 - std::cos(w * t))) << t;
    EXPECT_DOUBLE_EQ(c.drive.at(t).vx, 3.0 * std::sin(w * t)) << t;
  }
  EXPECT_EQ(c.drive.at(0).vx, 0.0);                                    // from rest
  EXPECT_NEAR(c.drive.at(1.0).x, x0 + 6.0 / std::numbers::pi, 1e-12);  // the far end: A T / pi
  // The swing either side of the motion's centre, A T / 2 pi, is what the box must hold twice and
  // what the cavity model reads as its amplitude.
  EXPECT_DOUBLE_EQ(displacementAmplitude(config.drive, 2.0), 3.0 / std::numbers::pi);
  EXPECT_DOUBLE_EQ(displacementAmplitude(config.drive, 8.0), 12.0 / std::numbers::pi);
  config.drive.form = DriveForm::Displacement;
  EXPECT_DOUBLE_EQ(displacementAmplitude(config.drive, 8.0), 3.0);
  // The box check uses that swing: A = 3 at T = 60 swings 28.6 d either side, too much for the
  // 60 d box with the 7 d disk (the displacement form's +-3 d fits).
  config.drive.form = DriveForm::Velocity;
  config.drive.period = 60.0;
  try {
    prepareCase(config);
    ADD_FAILURE() << "a 60 d box accepted a swing of 2 x 28.6 d";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("moving +-28.6479"), std::string::npos) << e.what();
  }
}

TEST(Case, SurfacedHeightIsTwoGrainsBelowTheSurfaceAtTheIntrudersTop) {
  RunConfig config;  // the disk: radius 3.5, its atoms reach the outline
  const Case c = prepareCase(config);
  double top = 0.0;
  for (double y : c.clump.offsetY) top = std::max(top, y + c.clump.atomRadius);
  EXPECT_NEAR(top, 3.5, 1e-9);
  EXPECT_DOUBLE_EQ(c.surfacedHeight, config.box.bedHeight - top - 2.0 * config.grains.dMax);
}

TEST(Case, RefusesWhatOnlyTheShapeShows) {
  RunConfig config;
  config.drive.amplitude = 40.0;  // the disk's sweep does not fit the 60 d box
  try {
    prepareCase(config);
    FAIL() << "expected box.width too narrow";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("box.width = 60 is too narrow"), std::string::npos) << e.what();
  }
  config = RunConfig{};
  config.intruder.y0 = 2.0;
  EXPECT_THROW(prepareCase(config), Error);  // no grain layers below the intruder
  config = RunConfig{};
  config.box.width = 1e6;
  config.box.bedHeight = 1e6;
  EXPECT_THROW(prepareCase(config), Error);  // an absurd bed is refused before anything is allocated
}

TEST(Case, WholeStepsRule) {
  EXPECT_EQ(wholeStepsIn(0.3, 1e-4), 3000u);  // 2999.9999999999995 in floating point
  EXPECT_EQ(wholeStepsIn(5.00005, 1e-4), 0u);
  EXPECT_EQ(wholeStepsIn(0.00005, 1e-4), 0u);  // less than one step
}

}  // namespace
}  // namespace wiggle
