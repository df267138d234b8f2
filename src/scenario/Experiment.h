#pragma once
// One case of the paper's experiment, from the bed to the rise rate (docs/PHYSICS.md §6-9, §13): validates the
// geometry, gets the bed (cache or made), drives the intruder, samples its trajectory, bins the
// vertical velocity by phase, takes field frames at the chosen phases, writes dumps, checkpoints
// every run.checkpoint_interval wall seconds, and writes the run directory's files.
#include <functional>
#include <string>
#include <vector>

#include "io/RunConfig.h"
#include "physics/Intruder.h"
#include "physics/World.h"

namespace wiggle {

struct RunOptions {
  std::string outDir = "wiggle-out";
  int threads = 0;          // OpenMP threads; 0 = as many as cores (OMP_NUM_THREADS honoured)
  bool resume = false;      // continue from the newest good checkpoint in outDir
  bool progressLine = true; // a progress line on stderr when it is a terminal
  // Test hook: stop (as if killed) after this many run-phase steps, leaving only checkpoints.
  std::uint64_t stopAfterSteps = 0;
  bool checkpointAtStop = false;  // with stopAfterSteps: write a checkpoint at that step first
};

struct RunOutcome {
  std::string status;   // "ok" | "stopped"
  double vy = 0.0, vySlope = 0.0;
  std::vector<std::string> warnings;  // what makes the result less than it seems (also in summary.json)
  std::string stateHash;
  std::string summaryPath;
};

// Geometric checks that need the shape: the box must hold the intruder plus twice the amplitude
// and a few grains on each side; the intruder must sit inside the bed with grains below and above.
// Throws wiggle::Error naming the key.
void checkGeometry(const RunConfig& config, const ClumpDef& clump);

// Everything `wiggle run` checks on the intruder before it makes a bed: the outline (which must fit
// in the bed before a single atom is placed, so a huge polygon cannot exhaust memory), the clump
// of atoms, then checkGeometry. Returns the clump; throws wiggle::Error naming the key.
ClumpDef checkedClump(const RunConfig& config);

// Releases the bed's intruder: x(t) = W/2 + A sin(2 pi t / T) (its amplitude ramped up over
// drive.ramp_periods periods when that is not 0), y free, t = 0 now.
void startDrive(World& world, const RunConfig& config);

RunOutcome runExperiment(const RunConfig& config, const RunOptions& options);

// Number of steps in `interval` at time step dt; throws when interval is not a whole number of steps.
std::uint64_t stepsIn(double interval, double dt, const char* key);

}  // namespace wiggle
