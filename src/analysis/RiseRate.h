#pragma once
// The intruder's rise rate from its sampled trajectory (docs/PHYSICS.md §9; docs/OUTPUT-FORMATS.md states the
// rule for users).
//
// Paper rule: V_y = (y_f - y_i) / (t_f - t_i), t_i = 0.1 t_total, t_f = t_total unless the intruder
// reached its final height earlier (a plateau, e.g. at the free surface). Plateau detection, made
// explicit here: average y over a window of max(T, 1) to remove the in-cycle wiggle; call y_end
// the averaged height at the end; t_plateau is the earliest time after t_i from which the averaged
// height stays within `plateauTolerance` (0.5 d) of y_end. It is used as t_f only when the intruder
// ends at the free surface (y_end >= surfacedHeight: its top within about two grains of the
// surface), travelled at least 4 tolerances (2 d) between t_i and the end, and the plateau lasts at
// least 10 % of the run. A pause inside the bed, or the end of a fast start-up transient, is not
// the paper's plateau and must not shorten the window.
// y_i and y_f are the raw sampled heights at t_i and t_f. The least-squares slope of y(t) over
// [t_i, t_f] is reported beside it.
#include <vector>

namespace wiggle {

struct TrajectorySample {
  double t, x, y, vx, vy, fy;  // time, intruder centre, velocity, vertical contact force
};

struct RiseRate {
  double vy = 0.0;        // paper's rule [sqrt(g d)]
  double slope = 0.0;     // least-squares slope over [t_i, t_f]
  double tInitial = 0.0, tFinal = 0.0;
  double yInitial = 0.0, yFinal = 0.0;
  bool plateau = false;   // t_f was moved before the end by the plateau rule
  double windowPeriods = 0.0;  // (t_f - t_i) / T: drive periods the rate is measured over

  // The intruder's height swings within each period; a window of fewer than kMinWindowPeriods
  // periods measures where in the cycle its ends fall more than any drift, so such a V_y is
  // reported with a warning (summary.json, console), never silently.
  static constexpr double kMinWindowPeriods = 2.0;
  bool windowTooShort() const { return windowPeriods < kMinWindowPeriods; }
  // The drive starts at full speed and sets the whole bed moving: the first 10-20 time units are
  // a start-up transient (docs/VALIDATION.md: the disk at T = 1 climbs 8 d in the first 12, then
  // stays). A window that ends before kSettledTime measures that transient, not a steady rise or
  // sink (a T = 1 run of t = 5 gave V_y = 0.74): it is reported with a warning too.
  static constexpr double kSettledTime = 20.0;
  bool withinStartupTransient() const { return tFinal < kSettledTime; }
};

RiseRate measureRiseRate(const std::vector<TrajectorySample>& samples, double totalTime, double period,
                         double surfacedHeight, double plateauTolerance = 0.5);

}  // namespace wiggle
