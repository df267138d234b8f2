#include "scenario/case/Case.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>

#include "core/Error.h"
#include "core/Format.h"
#include "io/Config.h"
#include "scenario/geometry/Clump.h"

namespace wiggle {

namespace {

// The count of run.dt steps in an interval io/Config has already checked to be whole.
std::uint64_t stepsOf(double interval, double dt, const char* key) {
  const std::uint64_t steps = wholeStepsIn(interval, dt);
  if (steps == 0)  // only a config that bypassed validateRunConfig gets here
    throw Error(std::string(key) + " = " + formatNumber(interval) + " is not a whole number of run.dt = " + formatNumber(dt) +
                " steps");
  return steps;
}

}  // namespace

HorizontalMotion driveKind(const DriveDef& drive) {
  if (drive.form == DriveForm::Velocity) return HorizontalMotion::VelocitySinusoid;  // a ramp is refused by validation
  return drive.rampPeriods > 0 ? HorizontalMotion::RampedSinusoid : HorizontalMotion::Sinusoid;
}

double displacementAmplitude(const DriveDef& drive, double period) {
  return driveKind(drive) == HorizontalMotion::VelocitySinusoid ? drive.amplitude * period / (2.0 * std::numbers::pi)
                                                                : drive.amplitude;
}

namespace {

void checkGeometry(const RunConfig& config, const ClumpDef& clump) {
  constexpr double kMaxGrains = 5e7;
  if (const double grains = estimatedGrains(config); grains > kMaxGrains)
    throw Error("box.width x box.bed_height = " + formatNumber(config.box.width) + " x " + formatNumber(config.box.bedHeight) +
                " needs about " + formatNumber(grains) + " grains, more than the " + formatNumber(kMaxGrains) + " wiggle accepts");
  double minX = 0, maxX = 0, minY = 0, maxY = 0;
  for (std::size_t a = 0; a < clump.offsetX.size(); ++a) {
    minX = std::min(minX, clump.offsetX[a] - clump.atomRadius);
    maxX = std::max(maxX, clump.offsetX[a] + clump.atomRadius);
    minY = std::min(minY, clump.offsetY[a] - clump.atomRadius);
    maxY = std::max(maxY, clump.offsetY[a] + clump.atomRadius);
  }
  const double width = maxX - minX;
  // Room for the intruder's sweep plus a few grain diameters between its images across the
  // periodic boundary, so it never meets itself.
  const double swing = displacementAmplitude(config.drive, config.drive.period);
  const double needed = width + 2.0 * swing + 4.0 * config.grains.dMax;
  if (config.box.width < needed)
    throw Error("box.width = " + formatNumber(config.box.width) + " is too narrow for the " +
                std::string(choiceName(config.intruder.shape)) + " (" + formatNumber(width) + " wide) moving +-" +
                formatNumber(swing) + ": need at least " + formatNumber(std::ceil(needed)));
  const double bottom = config.intruder.y0 + minY, top = config.intruder.y0 + maxY;
  if (bottom < 0.5 + 2.0 * config.grains.dMax)
    throw Error("intruder.y0 = " + formatNumber(config.intruder.y0) + " puts the intruder's bottom at y = " + formatNumber(bottom) +
                ", too near the base: need at least two grain layers below it");
  if (top > config.box.bedHeight - 2.0 * config.grains.dMax)
    throw Error("intruder.y0 = " + formatNumber(config.intruder.y0) + " puts the intruder's top at y = " + formatNumber(top) +
                ", outside or too near the top of the bed (box.bed_height = " + formatNumber(config.box.bedHeight) +
                "): need at least two grain layers above it");
}

}  // namespace

double bedPacking(BedPour pour) {
  // The made beds' grains times their mean area over width x bed height (d in [0.9, 1.1], 195 d
  // tall): random pours 0.847-0.850 (60 and 300 d wide), lattice pours 0.828-0.834. The
  // intruder's place counts as grains, so a small bed around a large intruder holds a few per cent
  // fewer (60 x 50 d: 0.81-0.83).
  return pour == BedPour::Random ? 0.85 : 0.83;
}

double estimatedGrains(const RunConfig& config) {
  const double a = config.grains.dMin, b = config.grains.dMax;
  const double meanArea = std::numbers::pi / 4.0 * (a * a + a * b + b * b) / 3.0;  // diameters uniform in [a, b]
  return config.box.width * config.box.bedHeight * bedPacking(config.bed.pour) / meanArea;
}

Case prepareCase(const RunConfig& config, BedNeeded bed) {
  Case c;
  c.config = config;
  c.shape = makeShape(config.intruder);
  const OutlineBox box = boundingBox(c.shape.outline);
  if (!(box.width() <= config.box.width && box.height() <= config.box.bedHeight))
    throw Error(std::string(config.intruder.shape == ShapeName::Polygon ? "intruder.vertices" : "intruder.shape") +
                ": the outline is " + formatNumber(box.width()) + " x " + formatNumber(box.height()) +
                ", larger than the bed (box.width = " + formatNumber(config.box.width) +
                ", box.bed_height = " + formatNumber(config.box.bedHeight) + ")");
  c.clump = makeClump(config.intruder, c.shape, config.grains.massModel, 1.0);
  checkGeometry(config, c.clump);
  // A pinned bed is never made, so it must be there before anything is written.
  if (bed == BedNeeded::Yes && !config.bed.file.empty() && !std::filesystem::is_regular_file(config.bed.file))
    throw Error("bed.file = " + config.bed.file + ": no such file");

  c.drive.kind = driveKind(config.drive);
  c.drive.x0 = 0.5 * config.box.width;
  c.drive.amplitude = config.drive.amplitude;
  c.drive.period = config.drive.period;
  c.drive.rampTime = static_cast<double>(config.drive.rampPeriods) * config.drive.period;
  c.drive.verticalFree = true;
  c.drive.rotationFree = config.intruder.rotation == IntruderRotation::Free;

  const double dt = config.run.dt;
  RunSchedule& s = c.steps;
  s.total = stepsOf(config.run.duration, dt, "run.duration");
  s.sampleEvery = stepsOf(config.run.sampleInterval, dt, "run.sample_interval");
  s.period = stepsOf(config.drive.period, dt, "drive.period");
  s.dumpEvery = config.run.dumpInterval > 0 ? stepsOf(config.run.dumpInterval, dt, "run.dump_interval") : 0;
  s.firstMeasured = static_cast<std::uint64_t>(std::llround(0.1 * static_cast<double>(s.total)));
  for (double p : config.fields.phases)
    s.fieldPhaseStep.push_back(static_cast<std::uint64_t>(std::llround(p / 20.0 * static_cast<double>(s.period))) %
                               s.period);

  double clumpTop = 0.0;
  for (std::size_t a = 0; a < c.clump.offsetY.size(); ++a)
    clumpTop = std::max(clumpTop, c.clump.offsetY[a] + c.clump.atomRadius);
  c.surfacedHeight = config.box.bedHeight - clumpTop - 2.0 * config.grains.dMax;
  return c;
}

void startDrive(World& world, const Case& c) {
  world.setIntruderMotion(c.drive);
  world.resetClock();
}

}  // namespace wiggle
