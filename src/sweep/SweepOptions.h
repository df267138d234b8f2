#pragma once
// What `wiggle sweep` is asked to do and what it reports (sweep/SweepRunner.h's runSweep), apart
// from the loops that do it, so that the coordinator (sweep/Coordinator.h) and the entry point
// share them without including each other.
#include <sys/types.h>

#include <cstddef>
#include <functional>
#include <iosfwd>
#include <string>

#include "sweep/TaskRunner.h"

namespace wiggle {
class MpiQueue;
}

namespace wiggle {

struct SweepOptions {
  std::string outDir;        // "" = sweep-<sweep name> in the working directory
  // Local: cases at once (0 = sweep.jobs, else the cores this process may use).
  // Under MPI: cases at once on each worker rank (0 = 1); rank 0 only coordinates.
  int jobs = 0;
  // Threads of each case (0 = sweep.threads_per_case, else cores / jobs locally, and under MPI
  // SLURM_CPUS_PER_TASK / jobs or 1).
  int threads = 0;
  bool dryRun = false;       // list the cases and the estimated cost; run nothing
  // `--case`: run only this case (its number from 1 or its name, as --dry-run lists them), making
  // its bed first if need be, for Slurm job arrays without MPI. Several such processes may work in
  // one sweep directory at once (not beside a whole-sweep run); each rebuilds results.csv from
  // every case directory when its case ends, so the table merges them all.
  std::string onlyCase;
  std::string executable;    // the wiggle binary the children run ("" = this process's binary)
  bool allowMpi = true;      // use MPI when launched by mpirun/srun with more than one process
  // MPI started already, for several sweeps in one job (the rounds of `wiggle boundary`): used
  // instead of starting it (which a process can do once). nullptr: runSweep starts it if launched so.
  MpiQueue* mpi = nullptr;
  bool progress = true;      // live status line on stderr when it is a terminal
  bool logToStderr = true;   // event lines on stderr when it is not a terminal (always in sweep.log)
  // The final summary line (SweepOutcome::summary) among those event lines; `wiggle sweep` turns it
  // off and prints the line itself, so that it is said once.
  bool summaryAsEvent = true;
  bool handleSignals = true; // SIGINT/SIGTERM: stop children at a checkpoint, write results, stop
  std::ostream* listing = nullptr;  // where --dry-run prints (nullptr = stdout)
  // Test hook: called on the coordinator when it starts a local child.
  std::function<void(const SweepTask&, pid_t)> onTaskStarted;
};

struct SweepOutcome {
  std::string outDir;
  std::size_t cases = 0, ok = 0, failed = 0, pending = 0;
  bool interrupted = false;
  int stopSignal = 0;        // the SIGINT/SIGTERM that interrupted it (exit status 128 + it)
  bool worker = false;       // this process was an MPI worker rank (it wrote nothing)
  std::string summary;       // one line for the user
};

}  // namespace wiggle
