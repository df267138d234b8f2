#pragma once
// `wiggle sweep` (docs/PHYSICS.md §12-13, docs/SWEEPS.md): runs every case of a sweep file, each in
// OUT/cases/<case name>/, locally as child processes or over MPI ranks, resumably, and keeps
// OUT/results.csv (ResultsTable.h) and OUT/sweep.log up to date.
//
// Order of work: the distinct beds that are not cached yet are made first, in parallel (one task
// per bed); a case starts once its bed is there, so no two workers ever make the same bed. A rerun
// skips cases whose summary.json says "ok", resumes interrupted ones from their checkpoints and
// retries failed ones.
#include <string>

#include "sweep/SweepOptions.h"

namespace wiggle {

// Runs (or with dryRun lists) the sweep. Throws wiggle::Error for a bad sweep file or directory;
// failed cases are not exceptions: they are counted in the outcome and recorded in results.csv.
SweepOutcome runSweep(const std::string& sweepFile, const SweepOptions& options);


}  // namespace wiggle
