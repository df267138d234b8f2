#pragma once
// The intruder's rise rate from its sampled trajectory (docs/PHYSICS.md §9; docs/OUTPUT-FORMATS.md states the
// rules for users). Two rules, both V_y = (y_f - y_i) / (t_f - t_i) from the raw sampled heights at
// t_i and t_f, differing in t_f:
//
// measureRiseRate, the run's `vy`: t_i = 0.1 t_total, t_f = t_total unless the intruder reached the
// free surface earlier (a plateau). Plateau detection: average y over a window of max(T, 1) to
// remove the in-cycle wiggle; call y_end the averaged height at the end; t_plateau is the earliest
// time after t_i from which the averaged height stays within `plateauTolerance` (0.5 d) of y_end.
// It is used as t_f only when the intruder ends at the free surface (y_end >= surfacedHeight: its
// top within about two grains of the surface), travelled at least 4 tolerances (2 d) between t_i
// and the end, and the plateau lasts at least 10 % of the run. A pause inside the bed, or the end
// of a fast start-up transient, is not a plateau for this rule.
//
// measureSettledRate, `vy_settled`: the paper's t_f, "the time at which the intruder is about to
// reach its final vertical position", wherever that position is (in the bed, at the surface, at the
// base): SettleRule below says exactly when an intruder counts as settled and where t_f then is.
// When it never settles, vy_settled == vy and t_settled is vy's t_f.
#include <algorithm>
#include <string>
#include <vector>

#include "analysis/Trajectory.h"

namespace wiggle {

// Where the rate is measured: from t_i = `from` to the end of the data used, `to` (samples after it
// are ignored, as if the run had ended there). A run's own window is paperWindow(t_total).
struct RateWindow {
  double from = 0.0, to = 0.0;
};
inline RateWindow paperWindow(double totalTime) { return {0.1 * totalTime, totalTime}; }

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
  // a start-up transient (study/VALIDATION.md: the disk at T = 1 climbs 8 d in the first 12, then
  // stays). A window that ends by kStartupTime measures that transient, not a steady rise or
  // sink (a T = 1 run of t = 5 gave V_y = 0.74): it is reported with a warning too.
  static constexpr double kStartupTime = 20.0;
  bool withinStartupTransient() const { return tFinal <= kStartupTime; }
  // A window that starts inside the transient and ends after it mixes the two: the share of it
  // before kStartupTime (the presets' t = 10-100: 0.11), and past kMostStartupShare it is warned of
  // too (a run to t = 30 measures over t = 3-30, 0.63 of it in the transient).
  static constexpr double kMostStartupShare = 0.25;
  double startupShare() const {
    return tFinal > tInitial ? std::clamp((kStartupTime - tInitial) / (tFinal - tInitial), 0.0, 1.0) : 1.0;
  }
  bool startsInStartupTransient() const { return !withinStartupTransient() && startupShare() > kMostStartupShare; }
};

// What makes a measured V_y less than it seems, in sentences: a window too short, inside the
// start-up transient, or starting in it (summary.json's warnings; `wiggle rate` on stderr).
std::vector<std::string> rateWarnings(const RiseRate& rate);

RiseRate measureRiseRate(const std::vector<TrajectorySample>& samples, RateWindow window, double period,
                         double surfacedHeight, double plateauTolerance = 0.5);

// The paper's t_f rule (docs/PHYSICS.md §9). Heights are first averaged over `smoothing(T)`, a
// whole number of drive periods at least kSmoothingTime long (the in-cycle wiggle and the bed's
// short fluctuations average out; one period leaves +-1 d of noise on a plateau at T = 2.5). The
// intruder has settled at t_s when, from t_s to the end, every averaged height lies within `band`
// of their mean (the final level), and
//   - it travelled at least kTravelBands bands from its averaged height at t_i to that level (a
//     wandering intruder that never went anywhere has not "reached" anything),
//   - both the approach [t_i, t_s] and the plateau [t_s, end] last at least kMinFraction of the
//     window (a start-up transient is not an approach; a short calm is not the final position),
//   - the plateau is flat: its least-squares slope is at most kFlatRatio of the approach's rate (a
//     steady climb, slow enough to stay within the band for a while, is not a plateau).
// The earliest such t_s is t_settled. The band is the rule's one parameter; `wiggle rate --band`
// measures how much an answer depends on it (docs/PHYSICS.md §9 has the figures).
struct SettleRule {
  double band = 1.0;                              // [d]: one grain diameter
  static constexpr double kSmoothingTime = 10.0;  // [sqrt(d/g)]
  static constexpr double kTravelBands = 4.0;
  static constexpr double kMinFraction = 0.1;
  static constexpr double kFlatRatio = 0.25;
  double smoothing(double period) const;  // the averaging window for drive period T
};

struct SettledRate {
  double vy = 0.0;        // (y(t_settled) - y(t_i)) / (t_settled - t_i) [sqrt(g d)]
  double tSettled = 0.0;  // the paper's t_f: when the intruder settled, else `unsettled`'s t_f
  bool settled = false;
};

// `unsettled` is measureRiseRate's result for the same window: what is reported when the intruder
// never settles (so vy_settled == vy then, and t_settled is vy's t_f).
SettledRate measureSettledRate(const std::vector<TrajectorySample>& samples, RateWindow window, double period,
                               const RiseRate& unsettled, const SettleRule& rule = {});

}  // namespace wiggle
