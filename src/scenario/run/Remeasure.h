#pragma once
// V_y after the fact: both rules (analysis/RiseRate.h) measured again from a finished run's
// trajectory.csv and config.toml, over its own window or any other (`wiggle rate`), and the settle
// rule's result recorded into a summary.json written before the rule existed.
#include <optional>
#include <string>
#include <vector>

#include "analysis/RiseRate.h"

namespace wiggle {

struct Case;

// Both rules over a window of a case's samples (its period, its surfaced height): the one
// computation behind summary.json (the run's own window), `wiggle rate` (any window) and the
// Python case (the window so far).
struct RunRates {
  RiseRate rate;
  SettledRate settled;
};
RunRates measureRunRates(const Case& run, const std::vector<TrajectorySample>& samples, RateWindow window,
                         const SettleRule& rule = {});

struct RemeasureRequest {
  std::optional<double> from, to;  // t_i and the end of the data used; default 0.1 x `to` and the run's end
  SettleRule rule;
  bool isRunsOwn() const { return !from && !to && rule.band == SettleRule{}.band; }
};

struct Remeasured {
  double period = 0.0;
  RiseRate rate;  // its tInitial and tFinal are the window measured
  SettledRate settled;
  // Without --to, a trajectory.csv that ends before run.duration (a LAMMPS run of the exported deck
  // for fewer steps, `lmp -var nsteps N`) is measured to its end, at this time; 0 otherwise.
  double cutShortAt = 0.0;
  // What this one bed's V_y over the window is worth (scenario/run/BedScatter.h).
  std::string scatterNote;
};

// Reads runDir/config.toml and runDir/trajectory.csv. Throws wiggle::Error naming the file or the
// option at fault (a window outside the data, a band that is not positive).
Remeasured remeasureRun(const std::string& runDir, const RemeasureRequest& request);

// Sets vy_settled, t_settled, settled and settle_band in runDir/summary.json (atomically; every
// other key as it was; unsettled, vy_settled and t_settled are the file's own vy and t_f). Throws wiggle::Error when there is no summary.json: the run has not finished.
void recordSettled(const std::string& runDir, const SettledRate& settled, const SettleRule& rule);

}  // namespace wiggle
