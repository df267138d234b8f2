#pragma once
// cells.csv of a sweep directory (docs/SWEEPS.md, "Beds as replicates"): one row per cell, a case
// without its seed (io/SweepSpec.h), with the mean V_y over the cell's beds, its standard deviation
// and standard error, and a verdict by one stated rule. Written beside results.csv, whole and
// atomically, every time results.csv is, so that `wiggle status` reads the cells without Python.
//
// The rule, here and only here on the C++ side (python/wiggleplot/cells.py is the Python side's
// one copy, and a test checks the two agree on a sweep's data): over the n beds with a V_y, mean
// and sample standard deviation sd (n - 1), se = sd / sqrt(n); the cell **rises** (mean > 0) or
// **sinks** (mean < 0) when n >= 2 and |mean| >= 2 se, else it is **not resolved**. One bed has
// no standard error: its sign is not a verdict ("one bed", never "rises"). Two standard errors of
// a cell's own beds are a weak test with few beds (Student's t puts the two-sided 95 % at 12.7 se
// for 2 beds, 4.30 for 3): the rule says where the data stand, not a significance.
#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "core/Choice.h"
#include "io/SweepSpec.h"
#include "sweep/ResultsTable.h"

namespace wiggle {

enum class CellVerdict { Rises, Sinks, NotResolved };
template <>
struct ChoiceNames<CellVerdict> {
  static constexpr std::array<std::string_view, 3> names{"rises", "sinks", "not resolved"};
};

// How far a cell's beds have got: every bed has a V_y, some have, none has yet.
enum class CellState { Done, PartRun, NotRun };
template <>
struct ChoiceNames<CellState> {
  static constexpr std::array<std::string_view, 3> names{"done", "part-run", "not run"};
};

// The rule's constants and its sentence (cells.csv's verdict_rule column, docs/SWEEPS.md).
inline constexpr double kCellResolvedStandardErrors = 2.0;
inline constexpr std::size_t kCellMinBeds = 2;
inline constexpr const char* kCellVerdictRule =
    "rises / sinks when |vy_mean| >= 2 vy_se with n >= 2, else not resolved";

struct CellStats {
  std::size_t n = 0;  // beds with a V_y
  double mean = 0.0;  // n >= 1
  double sd = 0.0;    // n >= 2: sample standard deviation (n - 1)
  double se = 0.0;    // n >= 2: sd / sqrt(n)
  CellVerdict verdict = CellVerdict::NotResolved;
};

// The statistics and verdict of a cell's V_y values (one per bed).
CellStats cellStats(const std::vector<double>& vy);

// The state of a cell with `n` of its `beds` run.
CellState cellState(std::size_t n, std::size_t beds);

// A cell in words for a console line: "+0.0886 +- 0.0025 (3 beds): rises", "+0.0886 (one bed: its
// sign is not a verdict; 1 of 2 beds run)", "no bed run yet (of 2)".
std::string cellInWords(const CellStats& stats, std::size_t beds);

// The fixed columns after the parameters' (cell and the parameters come first).
const std::vector<std::string>& cellColumnsAfterParameters();

// The whole of cells.csv for the sweep's cases as they stand (`results`, one per case).
std::string cellsCsv(const SweepSpec& spec, const std::vector<CaseResult>& results);

}  // namespace wiggle
