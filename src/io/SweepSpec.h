#pragma once
// A sweep file expanded into its cases (format in docs/CONFIG.md).
//
//   [sweep]              optional: name, jobs, threads_per_case, beds
//   [base.<section>]     a run config: the starting point of every case
//   [[case]]             optional list of partial configs (and an optional `name`) laid over base
//   [grid.<section>]     arrays of values; every combination is a case
//
// Cases = (each [[case]], or just base when there is none) x (cartesian product of the grid).
// Order: [[case]] in file order, then the grid odometer with the last grid key (in file order)
// varying fastest. Each case's name is built from the values that vary, so it does not depend on
// the case's position and survives adding values to the grid (resume matches runs by name).
//
// Beds as replicates: `beds = N` in [sweep] runs every case on N beds, box.seed 1..N, as if the grid
// ended with `box.seed = [1, ..., N]` (the seed varies fastest, so a cell's beds run together); with
// a [grid] box.seed of N values those are the beds. A cell is a case without its seed: the beds of
// one parameter point, whose V_y the sweep reports as a mean with its standard error (cells.csv,
// sweep/CellTable.h). Every sweep has cells, of one bed each when nothing varies the seed.
#include <cstddef>
#include <string>
#include <vector>

#include "io/RunConfig.h"

namespace wiggle {

struct SweepSettings {
  std::string name;         // sweep.name: label of the sweep (default: the file name's stem)
  int jobs = 0;             // sweep.jobs: cases run at once (0 = let `wiggle sweep` decide)
  int threadsPerCase = 0;   // sweep.threads_per_case: threads of each case (0 = cores / jobs)
  int beds = 0;             // sweep.beds: beds (box.seed 1..N) of every case; 0 = not given
};

// One column of results.csv: a key ("drive.period", or "case" for a [[case]] label) and this
// case's value as display text (configValueString: "5", "disk", "[0, 5]").
struct SweepParameter {
  std::string key;
  std::string value;
};

struct SweepCase {
  std::size_t index = 0;     // position in the expansion order, 0-based
  std::string name;          // unique within the sweep, safe as a directory name
  RunConfig config;          // fully resolved and validated
  std::vector<SweepParameter> parameters;  // same keys, same order, for every case
  std::size_t cell = 0;                    // index into SweepSpec::cells
};

// The key whose values are a cell's beds.
inline constexpr const char* kBedKey = "box.seed";

// A case without its seed: the beds (cases) of one parameter point, in case order.
struct SweepCell {
  std::string name;                // the case name without its seed part ("base" when nothing else varies)
  std::vector<std::size_t> cases;  // indices into SweepSpec::cases
};

struct SweepSpec {
  SweepSettings settings;
  std::vector<std::string> parameterKeys;  // the keys of SweepCase::parameters
  std::vector<SweepCase> cases;
  std::vector<SweepCell> cells;  // in the order of their first case
};

// Expands a sweep file's text. `sourceName` (the file name) starts every error message, and
// errors inside a case also name the case. Throws wiggle::Error.
SweepSpec parseSweepSpec(const std::string& tomlText, const std::string& sourceName);

// Reads and expands a sweep file.
SweepSpec loadSweepSpec(const std::string& path);

}  // namespace wiggle
