#pragma once
// A case: one run's configuration checked as a whole, with every number derived from it worked out
// once. `wiggle run`, `run --check`, sweeps (planning and beds), the LAMMPS export and the benchmarks
// start from a Case instead of repeating the checks and the arithmetic.
//
// Where checks live: io/Config checks each key on its own and the rules that need only the config
// (an interval must be a whole number of run.dt steps, wholeStepsIn); prepareCase adds the checks
// that need the intruder's outline or its clump of atoms (does it fit the box, is it inside the bed)
// and derives the rest.
#include <cstdint>
#include <string>
#include <vector>

#include "io/RunConfig.h"
#include "physics/Intruder.h"
#include "physics/World.h"
#include "scenario/geometry/Shape.h"

namespace wiggle {

// The run's schedule in steps of run.dt.
struct RunSchedule {
  std::uint64_t total = 0;          // run.duration
  std::uint64_t sampleEvery = 0;    // run.sample_interval
  std::uint64_t period = 0;         // drive.period
  std::uint64_t dumpEvery = 0;      // run.dump_interval; 0 = no dumps
  std::uint64_t firstMeasured = 0;  // 0.1 total: phase rates and field frames accumulate after it
  // Step within a period at which each of fields.phases is sampled: 10 phi / pi = p -> p / 20 of T.
  std::vector<std::uint64_t> fieldPhaseStep;
};

struct Case {
  RunConfig config;
  Shape shape;        // the outline: cavity model, geometry
  ClumpDef clump;     // the atoms the engine moves
  ClumpMotion drive;  // the intruder's motion once the run starts: x(t) = W/2 + A sin(2 pi t / T),
                      // its amplitude ramped up over drive.ramp_periods periods when that is not 0
  RunSchedule steps;
  // The intruder has surfaced when its centre reaches this height: its top two grain diameters
  // below the bed's nominal surface (the rise rate's plateau rule, analysis/RiseRate.h).
  double surfacedHeight = 0.0;
};

// Checks the config as a whole and derives the case. The outline must fit in the bed before a single
// atom is placed (so a huge polygon cannot exhaust memory); the box must hold the intruder plus
// twice the amplitude and a few grains on each side; the intruder must sit inside the bed with
// grains below and above; the bed must not be absurdly large. Throws wiggle::Error naming the key.
// `bed`: whether the case will be run from its bed (then a pinned bed.file must exist before anything
// is written) or is a finished or checkpointed run read again (wiggle rate, Case.load), which needs none.
enum class BedNeeded : bool { No, Yes };
Case prepareCase(const RunConfig& config, BedNeeded bed = BedNeeded::Yes);

// The drive's horizontal motion once the run starts (docs/PHYSICS.md §7): the sinusoid of
// drive.form, ramped when drive.ramp_periods > 0 (displacement form only: io/Config's validation
// refuses a ramp with the velocity form).
HorizontalMotion driveKind(const DriveDef& drive);

// How far the intruder swings either side of the centre of its motion at drive period `period`:
// A with drive.form = "displacement"; A T / (2 pi) with "velocity" (x goes from x0 to x0 + A T / pi
// and back). The box must hold twice this; the cavity model's amplitude is this.
double displacementAmplitude(const DriveDef& drive, double period);

// Releases the bed's intruder into the case's drive, y free, with the clock at t = 0.
void startDrive(World& world, const Case& c);

// The area fraction a made bed's grains fill below its surface, by how it was poured (bed.pour).
double bedPacking(BedPour pour);

// Estimated grains of a bed: box width x bed height x bedPacking / mean grain area, with the
// mean area of diameters uniform in [d_min, d_max]: (pi/4) (d_min^2 + d_min d_max + d_max^2) / 3.
double estimatedGrains(const RunConfig& config);

}  // namespace wiggle
