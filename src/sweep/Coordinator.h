#pragma once
// The two loops behind runSweep (sweep/SweepRunner.h): the coordinator, which hands the plan's
// tasks (beds, then cases, in case order) to local child processes and to MPI worker ranks and keeps
// results.csv and sweep.log, and the worker rank's loop. Internal to sweep/.
#include <cstddef>
#include <optional>
#include <string>

#include "sweep/MpiQueue.h"
#include "sweep/SweepOptions.h"
#include "sweep/SweepPlan.h"

namespace wiggle {

// Resolved settings of one sweep invocation.
struct SweepRunSettings {
  int jobs = 1;       // tasks at once (per worker rank under MPI)
  int threads = 1;    // threads of each task
  std::string executable;
};

// Rank 0 or the only process. `only`: the one case to run (--case), or nullopt for all of them.
SweepOutcome coordinateSweep(SweepPlan& plan, const SweepRunSettings& settings, const SweepOptions& options,
                             MpiQueue* mpi, std::optional<std::size_t> only);

// An MPI worker rank: asks rank 0 for tasks, runs them as children, reports back.
SweepOutcome runWorkerRank(const SweepPlan& plan, const SweepRunSettings& settings, MpiQueue& mpi);

}  // namespace wiggle
