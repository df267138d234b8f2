#pragma once
// `wiggle boundary` (docs/SWEEPS.md, "Finding a boundary"): where V_y changes sign as one numeric
// config key varies, decided by BoundarySearch (sweep/BoundarySearch.h), with one search per value
// of an optional second key (--over: a rise/sink map). The runs are the cases of a sweep in one
// directory, so everything a sweep does holds for them: beds cached per seed, cases resumed from
// their checkpoints, `wiggle status`/`report` on the directory.
//
// DIR/boundary.toml  the sweep file of every run asked for so far: [base] is the config, one
//                    [[case]] per run sets the --over key, the varied key and box.seed; rewritten
//                    (atomically) before each round; DIR/cases/, DIR/results.csv as any sweep's
// DIR/boundary.json  the searches: what was asked, every probe (value, V_y per bed, verdict, mean,
//                    standard error), crossings, neutral bands, the cost and what a grid would have
//                    cost; rewritten after each round
// DIR/boundary.csv   one row per crossing and per neutral band
//
// Rounds: every search's next() runs together (--jobs of them at once); their results decide the
// next round. A search is a pure function of its runs' results, so running the same command again
// asks for the same runs, finds them finished in DIR and goes on where it stopped.
#include <cstddef>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/RunConfig.h"
#include "sweep/BoundarySearch.h"
#include "sweep/SweepRunner.h"

namespace wiggle {

// Which V_y of a run decides: the paper's rule over the run (summary.json `vy`) or the paper's t_f
// rule (`vy_settled`, docs/PHYSICS.md section 9).
enum class RateRule { Paper, Settled };
const char* rateRuleName(RateRule rule);  // "paper", "settled"

struct BoundarySpec {
  RunConfig base;                    // the config, with its --set overrides
  std::string key = "drive.period";  // the varied key (a real number)
  BoundaryOptions options;           // its range, the scan, the resolution, the beds
  std::string overKey;               // "" = one search
  std::vector<double> overValues;    // one search per value
  RateRule rate = RateRule::Paper;
};

// Throws wiggle::Error naming the option at fault: the keys, the options, and every value the
// searches could probe (on the finest lattice their bisection can reach) makes a valid config, so
// that a search does not stop on a bad midpoint hours in.
void checkBoundarySpec(const BoundarySpec& spec);

// The run of bed `run.seed` (1, 2, ...) at `run.value` in search `search`: the base config with the
// --over key, the varied key and box.seed = base seed + run.seed - 1 set.
struct BoundaryCase {
  std::size_t search = 0;  // index into overValues (0 without --over)
  BoundaryRun run;
};
RunConfig boundaryCaseConfig(const BoundarySpec& spec, const BoundaryCase& c);

struct BoundaryCaseOutcome {
  bool ok = false;
  double vy = 0.0;           // by the spec's rate rule (ok)
  double wallSeconds = 0.0;  // ok
  std::string error;         // not ok
};

// How runs are made: as a sweep (SweepBoundaryRunner), or a stand-in in tests.
class BoundaryRunner {
 public:
  virtual ~BoundaryRunner() = default;
  // Makes (or finds finished) the runs all[firstNew...]; `all` holds every run asked for so far, in
  // the order asked. Returns one outcome per new run. Throws wiggle::Interrupted when stopped by a
  // signal (what finished stays finished).
  virtual std::vector<BoundaryCaseOutcome> run(const BoundarySpec& spec, const std::vector<BoundaryCase>& all,
                                               std::size_t firstNew) = 0;
};

// The runs as cases of a sweep in `options.outDir` (SweepRunner.h), `options` as for `wiggle sweep`.
// Under MPI (options.mpi set, this rank 0), each round is a sweep over the job's ranks: the worker
// ranks wait between rounds in serveBoundaryRounds, and are told to start one (MpiTag::Round) once
// its sweep file is written; releaseBoundaryWorkers ends their wait when the study is over.
class SweepBoundaryRunner : public BoundaryRunner {
 public:
  explicit SweepBoundaryRunner(SweepOptions options) : options_(std::move(options)) {}
  std::vector<BoundaryCaseOutcome> run(const BoundarySpec& spec, const std::vector<BoundaryCase>& all,
                                       std::size_t firstNew) override;

 private:
  SweepOptions options_;
};

// A worker rank of a boundary study under MPI: runs each round's tasks as rank 0 hands them out,
// reading the round's sweep file (options.outDir/boundary.toml) when told a round starts, until rank 0
// says the study is over. `options` as rank 0's (jobs and threads per worker rank), options.mpi set.
void serveBoundaryRounds(const SweepOptions& options);
// Rank 0: the study is over (or stopped): the worker ranks waiting between rounds leave.
void releaseBoundaryWorkers(MpiQueue& mpi);

// The sweep file of `cases` (DIR/boundary.toml).
std::string boundarySweepFile(const BoundarySpec& spec, const std::vector<BoundaryCase>& cases);

struct BoundaryResult {
  std::vector<BoundarySearch> searches;       // one per --over value (one without)
  std::vector<BoundaryCase> cases;            // every run, in the order asked
  std::vector<BoundaryCaseOutcome> outcomes;  // the same order
};

// Runs the searches to the end, writing outDir/boundary.json and boundary.csv after every round.
BoundaryResult runBoundary(const BoundarySpec& spec, BoundaryRunner& runner, const std::string& outDir);

// What a grid would have cost: probes evenly spaced at the finest spacing the search reached, each
// with as many beds as its most demanding probe needed.
struct GridComparison {
  double spacing = 0.0;
  std::size_t points = 0, beds = 0, cases = 0;
};
GridComparison gridComparison(const BoundarySpec& spec, const BoundarySearch& search);

nlohmann::json boundaryJson(const BoundarySpec& spec, const BoundaryResult& result);
std::string boundaryCsv(const BoundarySpec& spec, const BoundaryResult& result);
// One line per crossing and neutral band of each search, and one for the cost, for the console.
std::string boundaryLines(const BoundarySpec& spec, const BoundaryResult& result);

// The --dry-run listing: the first round's runs with their estimated cost, and how far the
// bisection may go.
std::string boundaryPlanListing(const BoundarySpec& spec);

}  // namespace wiggle
