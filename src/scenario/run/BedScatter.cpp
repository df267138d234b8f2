#include "scenario/run/BedScatter.h"

#include <cmath>

#include "core/Choice.h"
#include "core/Format.h"

namespace wiggle {

namespace {

// Box sizes, depths and times in the table are whole or half numbers: a match is to round-off.
bool same(double a, double b) { return std::fabs(a - b) <= 1e-6 * std::max(1.0, std::fabs(b)); }

constexpr const char* kSmallBed = "the small preset's bed (configs/small.toml: 60 x 50 d, intruder at y0 = 25 d)";
constexpr const char* kDepthBed =
    "the paper-depth preset's bed (configs/paper_depth.toml: 60 x 195 d, intruder at y0 = 90 d)";
constexpr const char* kClockWhere =
    "pooled over the shape's cells of two beds or more by the paper's clock in the 60 d box (results/paper_depth/"
    "table1_t1000, table1_t1000_bed2, factors_t1000; study/VALIDATION.md, the answer's Table 1)";

}  // namespace

const std::vector<MeasuredScatter>& measuredScatters() {
  // One bed's standard deviation of V_y (n - 1) over the beds of a cell (pooled over cells where
  // said), recomputed from the committed results/ by study/tools (findings.py, vy_tables.py).
  static const std::vector<MeasuredScatter> table = {
      {kSmallBed, 60, 50, 25, 10, 100, std::nullopt, 0.018,
       "the largest measured there: the disk at A = 3, T = 1 on three lattice beds (0.005 at T = 5), "
       "results/pour_protocol_small; study/FINDINGS.md takes it for every shape"},
      {kDepthBed, 60, 195, 90, 10, 100, std::nullopt, 0.045,
       "the disk at A = 5, T = 3 on three pours, results/paper_depth/box and seeds; study/FINDINGS.md takes it for "
       "every shape"},
      {kDepthBed, 60, 195, 90, 100, 1000, ShapeName::Disk, 0.0062, kClockWhere},
      {kDepthBed, 60, 195, 90, 100, 1000, ShapeName::Square, 0.0024, kClockWhere},
      {kDepthBed, 60, 195, 90, 100, 1000, ShapeName::RectNarrow, 0.0059, kClockWhere},
      {kDepthBed, 60, 195, 90, 100, 1000, ShapeName::RectWide, 0.0030, kClockWhere},
      {kDepthBed, 60, 195, 90, 100, 1000, ShapeName::Triangle, 0.0108, kClockWhere},
  };
  return table;
}

std::optional<MeasuredScatter> measuredScatterFor(const RunConfig& config, double from, double to) {
  for (const MeasuredScatter& m : measuredScatters()) {
    if (same(config.box.width, m.width) && same(config.box.bedHeight, m.bedHeight) && same(config.intruder.y0, m.y0) &&
        same(from, m.from) && same(to, m.to) && (!m.shape || *m.shape == config.intruder.shape))
      return m;
  }
  return std::nullopt;
}

std::string oneBedScatterNote(const RunConfig& config, double from, double to) {
  const std::string window = "t = " + formatNumber(from) + "-" + formatNumber(to);
  if (const std::optional<MeasuredScatter> m = measuredScatterFor(config, from, to))
    return "one bed; beds of this size scatter by about +-" + formatNumber(m->sigma) + " over this window (" + window +
           "; one bed's standard deviation of V_y on " + m->bed +
           (m->shape ? ", the " + std::string(choiceName(*m->shape)) + "'s" : std::string()) + ": " + m->where + ")";
  return "one bed: scatter unknown for a " + formatNumber(config.box.width) + " x " +
         formatNumber(config.box.bedHeight) + " d bed with the intruder at y0 = " + formatNumber(config.intruder.y0) +
         " over " + window + " (no committed study measured it); run `beds = N` in a sweep (docs/SWEEPS.md) to know it";
}

}  // namespace wiggle
