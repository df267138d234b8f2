#pragma once
// What one bed's V_y is worth: the between-bed scatter the committed replicate studies measured,
// one bed's standard deviation of V_y for a bed of a given size over a given window. The one table
// of such figures in the program; `wiggle run` and `wiggle rate` print its figure beside a single
// run's V_y ("one bed; beds of this size scatter by about +-X over this window", with where it was
// measured), or, where no study measured that bed and window, that the scatter is unknown and how
// to measure it (`beds = N` in a sweep, docs/SWEEPS.md). A single bed's sign is never a verdict.
//
// A figure applies to a run whose box (width, bed height), intruder depth (y0) and V_y window match
// the study's; a per-shape figure only to its shape. The studies' other settings (A, T, friction,
// the pour) are not matched: a figure is the size of the scatter to expect, not a standard error
// of that run. The numbers and where they come from: study/VALIDATION.md, "How much one bed tells".
#include <optional>
#include <string>
#include <vector>

#include "io/RunConfig.h"

namespace wiggle {

struct MeasuredScatter {
  const char* bed;                 // the bed in words ("the small preset's 60 x 50 d bed, intruder 25 d deep")
  double width, bedHeight, y0;     // [d] box.width, box.bed_height, intruder.y0
  double from, to;                 // [sqrt(d/g)] the V_y window t_i-t_f
  std::optional<ShapeName> shape;  // the shape it was measured for; none: taken for every shape
  double sigma;                    // [sqrt(g d)] one bed's standard deviation of V_y
  const char* where;               // how and where it was measured
};

// Every measured figure, in one table (BedScatter.cpp).
const std::vector<MeasuredScatter>& measuredScatters();

// The figure for a run of `config` with V_y over t = from to `to`, if a study measured one.
std::optional<MeasuredScatter> measuredScatterFor(const RunConfig& config, double from, double to);

// The sentence for a single run's V_y: "one bed; beds of this size scatter by about +-0.018 over
// this window (t = 10-100): ..." or "one bed: scatter unknown ...; run `beds = N` ...".
std::string oneBedScatterNote(const RunConfig& config, double from, double to);

}  // namespace wiggle
