#pragma once
// One case of the paper's experiment, from the bed to the rise rate (docs/PHYSICS.md §6-9, §13): from a
// prepared Case (scenario/case/Case.h), gets the bed (cache or made), drives the intruder, samples its trajectory, bins the
// vertical velocity by phase, takes field frames at the chosen phases, writes dumps, checkpoints
// every run.checkpoint_interval wall seconds, and writes the run directory's files.
#include <functional>
#include <string>
#include <vector>

#include "io/FileLock.h"
#include "io/RunConfig.h"
#include "physics/Intruder.h"
#include "physics/World.h"
#include "scenario/bed/BedMaker.h"
#include "physics/ThreadGovernor.h"
#include "scenario/case/Case.h"
#include "scenario/run/RunSummary.h"  // RunStatus

namespace wiggle {

struct RunOptions {
  std::string outDir = "wiggle-out";
  int threads = 0;          // OpenMP threads; 0 = as many as cores (OMP_NUM_THREADS honoured)
  // Adaptive: fewer while another process holds a core (physics/ThreadGovernor.h); Fixed: `threads`
  // always (`wiggle run --fixed-threads`: a benchmark of a thread count).
  ThreadPolicy threadPolicy = ThreadPolicy::Adaptive;
  bool resume = false;      // continue from the newest good checkpoint in outDir
  bool progressLine = true; // a progress line on stderr when it is a terminal
  // Test hook: stop (as if killed) after this many run-phase steps, leaving only checkpoints.
  std::uint64_t stopAfterSteps = 0;
  bool checkpointAtStop = false;  // with stopAfterSteps: write a checkpoint at that step first
};

// What a run ends with: the summary it wrote (a stopped run: status Stopped and nothing else), read
// as it is by the command's result line, and by a sweep from the file (sweep/ResultsTable.h).
struct RunOutcome {
  RunSummary summary;
  std::string summaryPath;

  // "V_y = ... (least-squares slope ...) d per sqrt(d/g)[; settled at t = ...: ...]; summary in ...":
  // the line `wiggle run` and a sweep's case print.
  std::string resultLine() const;
};

// A run directory's warnings.txt: the warnings about the run's history that must outlive the
// process that met them (a checkpoint that could not be read, so the run restarted from the bed),
// one per line; summary.json's warnings begin with them and `wiggle status` shows them.
std::string runWarningsPath(const std::string& runDir);
std::vector<std::string> readRunWarnings(const std::string& runDir);

// A run's start: its bed (obtainBed: cached or made now), the bed's contact history kept or cleared
// (run.bed_history), the drive started (startDrive, t = 0). `wiggle run` and the Python module both
// step from here, after World::evaluateForces. Throws wiggle::Error as obtainBed does.
CachedBed startRun(const Case& run, const BedProgress& progress = {});

// The run directory's rules: made if missing; held by one run at a time (the lock returned, on
// runLockPath, which the run keeps until it ends); a run already there is continued only with
// `resume`, and only by a config that can continue it; leftovers of a write cut short are removed;
// the config is written. Throws wiggle::Error naming the directory.
[[nodiscard]] FileLock prepareRunDirectory(const std::string& dir, const RunConfig& config,
                                           const std::string& configToml, bool resume);

// Whether `runDir` holds a run for `wiggle run --resume` to continue: a checkpoint (an interrupted
// run, or a finished one, which is then extended or rewritten), a summary.json (a finished run), or
// the progress.json of a run stopped before its first checkpoint (continued from its bed: the bed
// cache keeps a bed in the making). A directory with none of these never held a run (a mistyped
// --out): `wiggle run --resume` refuses it rather than start a new run there.
bool holdsRun(const std::string& runDir);

// The lock a run holds on its directory while it writes there: a second run given the same
// directory stops instead of writing beside it, and `wiggle status` sees which cases of a sweep
// are running whichever process runs them (array tasks leave no trace in results.csv until done).
std::string runLockPath(const std::string& runDir);

// Runs the case into options.outDir (or continues it there with options.resume).
RunOutcome runExperiment(const Case& run, const RunOptions& options);

}  // namespace wiggle
