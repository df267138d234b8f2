#pragma once
// Where V_y changes sign as one parameter varies (`wiggle boundary`, issue 32): the decisions, apart
// from how the runs are made. A search is a pure function of the results recorded so far: given the
// same results it asks for the same runs and reaches the same verdicts, so a search whose runs live
// in a resumable sweep directory continues where it stopped with the same decisions.
//
// The rule:
//   0. Values: a search probes only the lattice lo, lo + resolution, lo + 2 resolution, ..., hi
//      (each rounded to 12 significant digits, so 2.7 is 2.7 and not 2.7000000000000002): with
//      lo and resolution whole numbers of a key's quantum (run.dt for drive.period), every probe
//      is a valid value, and bisection ends exactly at the resolution.
//   1. Probes: a coarse scan of `points` lattice values as evenly spread over [lo, hi] as the
//      lattice allows, both ends included.
//   2. At each probe, beds (box.seed 1, 2, ...) are run until its sign is decided (the first
//      `minBeds` at once, then one at a time): at least `minBeds` beds and the mean V_y distinguishable from zero at 95 % (two-sided): |mean| >
//      t x standard error, with the beds' own scatter (standard error = sample standard deviation /
//      sqrt(n), t = Student's quantile for n - 1 degrees of freedom: 12.7 at 2 beds, 4.30 at 3,
//      3.18 at 4, 2.78 at 5; a fixed "2 standard errors" with a scatter estimated from 2 or 3 beds
//      decides wrongly far more often than 1 in 20), or, when `knownScatter` (one bed's standard
//      deviation, measured elsewhere) is given, standard error = knownScatter / sqrt(n) and t = 1.96.
//      After `maxBeds` beds without that, the probe is neutral: V_y indistinguishable from zero
//      there, a result, not a failure.
//   3. Once every probe is decided, each pair of neighbouring probes whose verdicts differ (rising,
//      sinking or neutral) more than one lattice step apart gets a probe at the lattice value
//      nearest its midpoint; repeat.
//   4. The verdicts in order of the value: a change from sinking to rising (or back) between two
//      signed probes is a crossing, bracketed by them; a run of neutral probes is a neutral band,
//      bracketed by the signed probes on either side (or the range's ends), inside a crossing or not.
// A crossing inside one interval of the coarse scan that is undone within the same interval (two
// crossings closer together than the scan's spacing) is not seen: the scan's spacing is the
// resolution of what can be found at all, and is reported.
// A run that fails is recorded as such: its probe is set aside (reported, never decided) and its
// neighbours are compared across it (past a failed midpoint, at the quarter points).
#include <cstddef>
#include <map>
#include <optional>
#include <utility>
#include <vector>

namespace wiggle {

struct BoundaryOptions {
  double lo = 0.0, hi = 0.0;  // the range of the varied value
  int points = 5;             // the coarse scan, ends included (>= 2)
  double resolution = 0.0;    // the lattice step: bisection ends with neighbours this far apart (> 0)
  int minBeds = 2, maxBeds = 4;
  double knownScatter = 0.0;  // one bed's standard deviation of V_y, when known; 0: from the beds themselves
};

// The lattice of a search's values (rule 0): latticeIntervals(o) + 1 values, the last one hi (the
// last interval is shorter when the resolution does not divide the range).
std::size_t latticeIntervals(const BoundaryOptions& options);
double latticeValue(const BoundaryOptions& options, std::size_t index);

// Student's t quantile at 0.975 for `dof` degrees of freedom (>= 1; the normal's 1.96 beyond 30).
double studentT975(int dof);

// Throws wiggle::Error naming the option at fault.
void checkBoundaryOptions(const BoundaryOptions& options);

enum class Verdict { Undecided, Rising, Sinking, Neutral, Failed };
const char* verdictName(Verdict verdict);

struct Probe {
  std::size_t index = 0;  // on the lattice
  double value = 0.0;
  std::vector<double> vy;  // by bed: vy[k] is box.seed k + 1
  bool failed = false;     // a run of this probe failed
  Verdict verdict = Verdict::Undecided;
  double mean = 0.0, standardError = 0.0;  // over vy (with knownScatter, that / sqrt(n); else 0 below two beds)
};

// One run the search needs: the probe's value and the bed (box.seed, from 1).
struct BoundaryRun {
  double value = 0.0;
  int seed = 1;
  bool operator==(const BoundaryRun&) const = default;
};

// A change of sign between two signed probes next to each other among the decided ones: the
// crossing lies in [below, above]. Neutral probes between them (V_y indistinguishable from zero)
// are its neutral band [neutralLo, neutralHi]; the bisection brackets each edge of it.
struct Crossing {
  double below = 0.0, above = 0.0;
  Verdict from = Verdict::Undecided, to = Verdict::Undecided;  // Sinking -> Rising or Rising -> Sinking
  std::optional<double> neutralLo, neutralHi;
};

// A run of neighbouring neutral probes [first, last], between the signed probes `below` and
// `above` (none at an end of the range): "V_y is indistinguishable from zero over [first, last]".
// Inside a crossing or not (sinking on both sides: V_y touches zero without changing sign).
struct NeutralBand {
  double first = 0.0, last = 0.0;
  std::optional<double> below, above;
};

class BoundarySearch {
 public:
  explicit BoundarySearch(const BoundaryOptions& options);

  // Records what a run gave. A value that is not a probe, or a bed out of turn, is an internal
  // error (wiggle::Error): the runs come from next().
  void record(const BoundaryRun& run, double vy);
  void recordFailure(const BoundaryRun& run);

  // The runs to make now, all independent of each other (they may run at once); empty when the
  // search is over.
  std::vector<BoundaryRun> next() const;
  bool finished() const { return next().empty(); }

  // Every probe so far, by value.
  const std::vector<Probe>& probes() const { return probes_; }
  // From the decided probes (a search not yet finished gives what it has so far).
  std::vector<Crossing> crossings() const;
  std::vector<NeutralBand> neutralBands() const;

 private:
  double sameValueTolerance() const;  // two values this close are one probe
  int bedsAsked(const Probe& probe) const;  // next() asks for beds up to this one
  Probe& probeAt(double value);
  void decide(Probe& probe) const;
  void refine();

  BoundaryOptions options_;
  std::vector<Probe> probes_;  // sorted by value
  std::map<std::pair<std::size_t, int>, double> waiting_;  // (probe index, seed): a bed recorded before an earlier one
};

}  // namespace wiggle
