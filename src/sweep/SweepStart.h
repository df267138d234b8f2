#pragma once
// A sweep directory's sweep.json: how the last `wiggle sweep` (or `wiggle boundary`) over it was
// started, written by the sweep as it starts (sweep/Coordinator) and read by `wiggle status` and
// `wiggle report` (sweep/SweepStatus), which read this data rather than sweep.log's lines for
// people. Written atomically (io/AtomicFile). docs/SWEEPS.md ("What it does") lists its fields.
#include <optional>
#include <string>
#include <vector>

namespace wiggle {

// A bed the sweep had to make when it started: a deep or wide bed takes hours in which no case
// runs, so the time to go counts it until the cache holds it.
struct BedToMake {
  std::string key;
  std::string cachePath;          // made once this file exists
  double estimatedSeconds = 0.0;  // the sweep plan's estimate, in seconds of one core (PlannedBed)
};

struct SweepStart {
  std::string name;  // [sweep] name
  int jobs = 0;      // cases at once (all MPI worker ranks' jobs together); 0 for a Slurm array's tasks
  int threads = 0;   // OpenMP threads per case
  // Nothing in a sweep.json written before the beds were recorded: then what the beds cost is not known.
  std::optional<std::vector<BedToMake>> beds;
};

std::string sweepStartPath(const std::string& sweepDir);
// The sweep directory's lock: a whole sweep holds it alone, one-case tasks (`--case N`) together;
// `wiggle status` reads who holds it.
std::string sweepLockPath(const std::string& sweepDir);
// A whole sweep's start replaces the file; an array task's (`--case N`, jobs 0) writes it only when
// there is none, so that a sweep's own figures are not overwritten by its array tasks.
void writeSweepStart(const std::string& sweepDir, const SweepStart& start);
// The last start, or nothing when there is none (a sweep by a wiggle that did not write it) or it
// cannot be read.
std::optional<SweepStart> readSweepStart(const std::string& sweepDir);

}  // namespace wiggle
