#pragma once
// What a run observes while it steps (`wiggle run` and the Python module's Case alike): after every
// step, the phase bins (after t_i) and the trajectory samples, which read only the intruder; at the
// steps that need the grains, the field frames and the dump frames. All of it is kept in the
// RunState and the FieldObserver that a checkpoint saves, so a resumed run observes on bit for bit.
#include <cstdint>
#include <functional>
#include <string>

#include "analysis/FieldObserver.h"
#include "physics/World.h"
#include "scenario/case/Case.h"
#include "scenario/run/Checkpoint.h"

namespace wiggle {

class RunObservers {
 public:
  // dumpPath: the dump file frames are appended to; empty for a run that keeps no dump file (the
  // Python case), which then takes no dump frames whatever run.dump_interval says.
  RunObservers(const Case& run, RunState& state, FieldObserver& fields, std::string dumpPath)
      : run_(run), state_(state), fields_(fields), dumpPath_(std::move(dumpPath)) {}

  // The intruder's sample of the world's current step (the run's first, at t = 0).
  void sample(const World& world) { state_.sample(world); }
  // A dump frame of the world's current step, appended to the dump file.
  void dumpFrame(const World& world);

  // Steps the world towards step `end`, observing every step as above, and returns at `end` or
  // after the first step for which stopAt (when given) is true. The steps between two observations
  // of the grains run as one stretch (World::runWatchingIntruder's fused passes).
  void stepTowards(World& world, std::uint64_t end, const std::function<bool(std::uint64_t)>& stopAt = {});

 private:
  // Whether the grains are observed after this step: a field frame or a dump frame.
  bool needsGrainsAt(std::uint64_t step) const { return fieldPhaseAt(step) || dumpAt(step); }
  bool dumpAt(std::uint64_t step) const {
    return !dumpPath_.empty() && run_.steps.dumpEvery && step % run_.steps.dumpEvery == 0;
  }
  // 1 + the fields.phases entry whose frame is taken after this step; 0 for none.
  std::size_t fieldPhaseAt(std::uint64_t step) const;

  const Case& run_;
  RunState& state_;
  FieldObserver& fields_;
  std::string dumpPath_;
};

}  // namespace wiggle
