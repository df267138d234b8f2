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
#include "scenario/case/Case.h"       // estimatedGrains
#include "scenario/cost/CostModel.h"  // SpeedBasis; the estimates the plan prints

namespace wiggle {

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

// The beds (indices into plan.beds) that a run of the plan makes: all of them, or with `only`
// (--case) just the one that case waits for, if any: the other cases' beds are other tasks' work.
std::vector<std::size_t> bedsMadeBy(const SweepPlan& plan, std::optional<std::size_t> only);

// The dry-run listing of a plan for `jobs` cases at once with `threads` threads each.
std::string dryRunListing(const SweepPlan& plan, int jobs, int threads);

}  // namespace wiggle
