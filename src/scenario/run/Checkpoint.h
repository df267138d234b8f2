#pragma once
// A run's checkpoint (DIR/checkpoint.bin; the one before it is kept as DIR/checkpoint.prev.bin):
// the resolved config's TOML, the World, the run's own bookkeeping (RunState) and the field sums,
// framed as a state file of kind "checkpoint" (io/StateFile.h: magic, version, checksum). A
// checkpoint is used only when every part reads back whole and it belongs to the same config.
#include <cstdint>
#include <string>
#include <vector>

#include "analysis/FieldObserver.h"
#include "analysis/RiseRate.h"
#include "core/BinaryStream.h"
#include "io/RunConfig.h"
#include "physics/World.h"
#include "scenario/case/Case.h"

namespace wiggle {

inline constexpr int kPhaseBins = 20;  // 10 phi / pi in [0, 20), one bin per unit (docs/PHYSICS.md §9)

// Everything the run loop accumulates besides the World.
struct RunState {
  std::vector<TrajectorySample> samples;
  // The turn at each sample of an intruder that may turn; empty when it may not, and for a run resumed
  // from a checkpoint written before turns were kept (it then gets none: a column is whole or absent).
  std::vector<SpinSample> spins;
  std::vector<double> phaseSum = std::vector<double>(kPhaseBins, 0.0);
  std::vector<std::uint64_t> phaseCount = std::vector<std::uint64_t>(kPhaseBins, 0);
  std::uint64_t dumpBytes = 0;     // length of dumps/dump.lammpstrj at this state
  double runWallSeconds = 0.0;     // stepping time so far (for ns per particle-step)
  double bedWallSeconds = 0.0;
  std::string bedKey;
  bool bedFromCache = false;

  // A trajectory sample of the world's intruder now (and its turn, when it may turn).
  void sample(const World& world) {
    if (world.intruderMotion().rotationFree && spins.size() == samples.size())
      spins.push_back({world.intruderSpin().angle, world.intruderSpin().omega});
    const ClumpState& intruder = world.intruder();
    samples.push_back({world.time(), intruder.x, intruder.y, intruder.vx, intruder.vy, intruder.contactFy});
  }
  // What a run records of the intruder after each step (the one rule, used by `wiggle run` and the
  // Python module): its v_y in the step's phase bin once past t_i, and a sample every
  // run.sample_interval.
  void recordStep(const RunSchedule& steps, const World& world, std::uint64_t step) {
    if (step > steps.firstMeasured) {
      const auto bin = static_cast<std::size_t>((step % steps.period) * kPhaseBins / steps.period);
      phaseSum[bin] += world.intruder().vy;
      ++phaseCount[bin];
    }
    if (step % steps.sampleEvery == 0) sample(world);
  }

  void save(BinaryWriter& out) const;
  void load(BinaryReader& in);
};

struct Checkpoint {
  World world;
  RunState state;
  FieldObserver fields;
};

std::string checkpointPath(const std::string& runDir);
std::string previousCheckpointPath(const std::string& runDir);

// Moves the current checkpoint to checkpoint.prev.bin, then writes the new one atomically, so a
// crash at any moment leaves at least one good checkpoint. Throws wiggle::Error when it cannot write.
void writeCheckpoint(const std::string& runDir, const std::string& configToml, const World& world,
                     const RunState& state, const FieldObserver& fields);

// Whether a run made with `past` may be continued with `now`: "" when it may, else why not, naming
// the key. Only keys on which nothing that has already happened depends may change: run.duration
// (longer only: a finished run is extended), run.plot and run.checkpoint_interval.
std::string whyRunCannotContinue(const RunConfig& past, const RunConfig& now);

// The checkpoint in a file's bytes (`name` starts every error message). `configToml` is
// toToml(config): a checkpoint of a run that `config` cannot continue (whyRunCannotContinue) is
// refused; one written by a version that did not have some key yet counts as holding that key's
// default (so a long run survives an upgrade that adds keys, unless it sets one of them). Throws wiggle::Error for anything
// truncated, corrupt, foreign or inconsistent.
Checkpoint parseCheckpoint(const std::string& file, const std::string& name, const RunConfig& config,
                           const std::string& configToml);

}  // namespace wiggle
