#pragma once
// What a sweep has to do (docs/PHYSICS.md §12-13, docs/SWEEPS.md): the cases of a sweep file, each with its run
// directory and what is already there, grouped by the bed they share, with an estimated cost.
//
// Tasks are of two kinds: making a bed (one per distinct bed key whose bed is not cached yet) and
// running a case. A case becomes runnable once its bed task is done, so two workers never make the
// same bed at once; beds are made just before their first case (SweepRunner hands work out in case
// order), in parallel when there are workers for them. Every MPI rank builds the same plan from
// the same file (the expansion is deterministic), so only task indices travel between ranks.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "io/SweepSpec.h"
#include "scenario/Case.h"  // estimatedGrains

namespace wiggle {

// --- cost model (dry run and ETA before any case has finished) ----------------------------------
// One place for the numbers; docs/SWEEPS.md quotes them and says how they were measured.
struct CostModel {
  // Wall time per particle per step of one single-threaded case on this project's reference
  // machine [ns]: 55 ns, bench/run_bench.sh on the configs/small.toml bed, 1 thread, median of
  // 3 rounds on the AMD EPYC (Zen 3) machine (docs/PERFORMANCE.md, session 3, 2026-11-22).
  static constexpr double nsPerParticleStep = 55.0;
  // Simulated time a bed spends per nominal batch (bed.batch_height of the final bed: falling and
  // settling) and on the final relaxation, in sqrt(d/g). Measured on a 60 x 195 d bed (default
  // bed keys, 2026-11-24): 14 poured batches for 10 nominal ones took t = 99, the relaxation to
  // bed.rest_energy = 1e-6 about 40 more.
  static constexpr double bedTimePerBatch = 10.0;
  static constexpr double bedRelaxTime = 40.0;
  // The relaxation of a carved bed (bed.cavity = "carved") after its cut, and of any bed with
  // bed.relax_damping > 0. Measured on the paper-depth preset (seed 7, one quiet core, 2026-11-25):
  // a cut relaxed in 152 s undamped (about 53 time units at 23 ns per particle-step), 16 s with
  // bed.relax_damping = 2 (about 5.6).
  static constexpr double carvedRelaxTime = 55.0;
  static constexpr double dampedRelaxTime = 6.0;
};

// The ns per particle-step the estimates use, and where it comes from: the median of this machine's
// last one-thread runs (scenario/SpeedRecord.h) when it has recorded any on this CPU, else
// CostModel::nsPerParticleStep (the reference machine's figure).
struct SpeedBasis {
  double ns = CostModel::nsPerParticleStep;
  std::string source;  // for people: "the median of this machine's last 9 one-thread runs (PATH)"
};
SpeedBasis speedBasis(const RunConfig& config);

// Estimated wall seconds of a case's run phase (bed excluded) at `nsPerParticleStep`.
double estimatedRunSeconds(const RunConfig& config, double nsPerParticleStep);
// Estimated wall seconds of making the case's bed at `nsPerParticleStep`; for a carved bed, the
// cut and its relaxation, plus pouring its base bed when `withBase`.
double estimatedBedSeconds(const RunConfig& config, double nsPerParticleStep, bool withBase = true);

// --- the plan -----------------------------------------------------------------------------------
enum class CaseState {
  Pending,  // to run (from its newest checkpoint if it has one)
  Done,     // summary.json with status "ok" and the same config: skipped
  Failed,   // cannot run (geometry, a different config already in its directory, its bed failed)
};

struct PlannedCase {
  std::size_t index = 0;      // into SweepSpec::cases
  std::string dir;            // absolute or as given: <outDir>/cases/<name>
  std::string runDir;         // relative to the sweep directory: cases/<name>
  std::string bedKey;         // "" when the clump cannot be made (then state is Failed)
  int bedTask = -1;           // index into SweepPlan::beds of the bed it waits for; -1 = none
  CaseState state = CaseState::Pending;
  bool hasCheckpoint = false; // an interrupted run that will resume
  std::string error;          // why it failed (state Failed)
  double estimatedParticles = 0.0;
  std::uint64_t steps = 0;
};

struct PlannedBed {
  std::string key;
  std::string configPath;     // <outDir>/beds/bed-<key>.toml: the config the bed task reads
  std::size_t firstCase = 0;  // the case whose config makes the bed
  std::string cachePath;      // where obtainBed keeps it
  double estimatedSeconds = 0.0;  // at SweepPlan::speed
};

struct SweepPlan {
  SweepSpec spec;
  std::string outDir;
  std::vector<PlannedCase> cases;   // same order as spec.cases
  std::vector<PlannedBed> beds;     // beds to make (not cached yet, needed by a pending case)
  std::size_t distinctBeds = 0;     // bed keys among all cases (cached or not)
  SpeedBasis speed;                 // what the estimates (beds, dry run, ETA before a case ends) use
};

// Expands the plan: for each case its directory and state (reads summary.json and config.toml of
// existing case directories; does not write anything).
SweepPlan makeSweepPlan(SweepSpec spec, const std::string& outDir);


// The dry-run listing of a plan for `jobs` cases at once with `threads` threads each.
std::string dryRunListing(const SweepPlan& plan, int jobs, int threads);

}  // namespace wiggle
