// `wiggle boundary [CONFIG.toml] --range LO:HI --out DIR [--vary KEY] [--points N] [--resolution R]
// [--beds MIN:MAX] [--scatter S] [--over KEY=V1,V2,...] [--rate paper|settled] [--jobs N]
// [--threads T] [--set ...] [--dry-run]` (docs/SWEEPS.md, "Finding a boundary").
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>

#include "Arguments.h"
#include "Commands.h"
#include "PathChecks.h"
#include "core/Error.h"
#include "core/Format.h"
#include "io/Config.h"
#include "physics/ForceKernels.h"
#include "sweep/BoundaryStudy.h"
#include "sweep/MpiQueue.h"

namespace wiggle::cli {

namespace {

struct BoundaryArgs {
  std::string config;
  std::vector<std::string> sets;
  std::string key = "drive.period";
  std::string range, beds = "2:4", over, rate = "paper";
  std::string out;
  int points = 5;
  std::optional<double> resolution;  // none: not given (required)
  double scatter = 0.0;
  int jobs = 0, threads = 0;
  bool dryRun = false;
};

int parseCount(const std::string& text, const std::string& what) {
  const double v = parseNumber(text, what);
  if (v != std::floor(v) || v < 0 || v > 1000) throw Error(what + ": '" + text + "' is not a whole number of beds");
  return static_cast<int>(v);
}

// "A:B" -> {A, B}.
std::pair<std::string, std::string> pairOf(const std::string& text, char sep, const std::string& what,
                                           const std::string& form) {
  const std::vector<std::string> parts = split(text, sep);
  if (parts.size() != 2) throw Error(what + " " + text + ": expected " + form);
  return {parts[0], parts[1]};
}

BoundarySpec specOf(const BoundaryArgs& a) {
  BoundarySpec spec;
  spec.base = loadRunConfig(a.config.empty() ? std::nullopt : std::optional<std::string>(a.config), a.sets);
  spec.key = a.key;
  if (a.range.empty()) throw Error("--range LO:HI is required (the values of " + a.key + " to search)");
  const auto [lo, hi] = pairOf(a.range, ':', "--range", "LO:HI");
  spec.options.lo = parseNumber(lo, "--range");
  spec.options.hi = parseNumber(hi, "--range");
  spec.options.points = a.points;
  if (!a.resolution) throw Error("--resolution R is required (the step of the values searched: LO + k R)");
  if (!(*a.resolution > 0)) throw Error("--resolution " + formatNumber(*a.resolution) + ": must be positive");
  spec.options.resolution = *a.resolution;
  const auto [bedMin, bedMax] = pairOf(a.beds, ':', "--beds", "MIN:MAX");
  spec.options.minBeds = parseCount(bedMin, "--beds");
  spec.options.maxBeds = parseCount(bedMax, "--beds");
  if (!(a.scatter >= 0)) throw Error("--scatter " + formatNumber(a.scatter) + ": must be zero or positive");
  spec.options.knownScatter = a.scatter;
  if (!a.over.empty()) {
    const auto [key, values] = pairOf(a.over, '=', "--over", "KEY=V1,V2,...");
    spec.overKey = key;
    for (const std::string& v : split(values, ',')) spec.overValues.push_back(parseNumber(v, "--over " + key));
  }
  if (a.rate == "paper")
    spec.rate = RateRule::Paper;
  else if (a.rate == "settled")
    spec.rate = RateRule::Settled;
  else
    throw Error("--rate " + a.rate + ": expected paper or settled");
  return spec;
}

}  // namespace

void addBoundaryCommand(CLI::App& app) {
  auto args = std::make_shared<BoundaryArgs>();
  auto* cmd = app.add_subcommand(
      "boundary", "Find where V_y changes sign as a key varies (bisection, beds until the sign is decided), resumably");
  cmd->add_option("config", args->config, "Run config (TOML); none = the embedded default case");
  cmd->add_option("--set", args->sets, "Override a key of the config: --set drive.amplitude=3 (repeatable)")
      ->allow_extra_args(false);
  cmd->add_option("--vary", args->key, "The key to vary (a real number)")->capture_default_str();
  cmd->add_option("--range", args->range, "LO:HI, the values of the varied key to search (required)");
  cmd->add_option("--points", args->points, "Values of the first, coarse scan, ends included")
      ->capture_default_str()
      ->check(CLI::Range(2, 1000));
  cmd->add_option("--resolution", args->resolution,
                  "The step of the values searched, LO + k R (required): a change of sign is bracketed to it");
  cmd->add_option("--beds", args->beds,
                  "MIN:MAX beds (box.seed = the config's seed, +1, ...) per value: at least MIN, more until the sign "
                  "of the mean is decided, at most MAX (then the value is neutral)")
      ->capture_default_str();
  cmd->add_option("--scatter", args->scatter,
                  "One bed's standard deviation of V_y when it is known (then 1.96 standard errors decide; default: "
                  "Student's t with the beds' own scatter)");
  cmd->add_option("--over", args->over, "KEY=V1,V2,...: one search per value of a second key (a rise/sink map)");
  cmd->add_option("--rate", args->rate,
                  "Which V_y decides: paper (summary.json vy) or settled (vy_settled, the paper's t_f rule)")
      ->capture_default_str();
  cmd->add_option("--out", args->out, "The search's directory (required; made if missing, its parent must exist)");
  cmd->add_option("--jobs", args->jobs, "Runs at once (default: one per core)")->check(CLI::Range(1, 100000));
  cmd->add_option("--threads", args->threads, "Threads per run (default: cores / jobs)")->check(CLI::Range(1, 1024));
  cmd->add_flag("--dry-run", args->dryRun,
                "Check everything, list the first round and its estimated cost; run nothing");
  cmd->footer(
      "The runs are the cases of a sweep in DIR (DIR/boundary.toml, DIR/cases/, DIR/results.csv): wiggle status\n"
      "and wiggle report read it. DIR/boundary.json and DIR/boundary.csv hold the probes, crossings and neutral\n"
      "bands; wiggle plot DIR draws them. Run the same command again to resume: finished runs are read back and\n"
      "the searches continue with the same decisions. Under mpirun or srun, rank 0 searches and the other ranks\n"
      "run each round's cases (docs/SWEEPS.md).\n"
      "Exit status: 0 when every search finished, 1 when a run failed (its value is set aside and reported),\n"
      "2 for bad input, 130 or 143 when SIGINT or SIGTERM stopped it (run the same command to resume).");
  cmd->callback([args] {
    defaultSimdLevel();  // a bad WIGGLE_SIMD is bad input before anything is written
    if (!args->config.empty()) requireInputFile(args->config, "config file");
    const BoundarySpec spec = specOf(*args);
    requireOutputDirectory("--out", args->out);  // a dry run checks it too; none given is checked below
    if (args->dryRun) {
      if (MpiQueue::launcherRank() == 0) std::fputs(boundaryPlanListing(spec).c_str(), stdout);  // one, under mpirun
      return;
    }
    if (args->out.empty()) throw Error("--out DIR is required (the search's directory)");
    requireWritableOutputDirectory("--out", args->out);
    SweepOptions options;
    options.outDir = args->out;
    options.jobs = args->jobs;
    options.threads = args->threads;
    // Under mpirun or srun, one MPI for every round: rank 0 searches, the others run its rounds' cases.
    std::unique_ptr<MpiQueue> mpi;
    if (MpiQueue::launchedAsMultipleProcesses()) {
      mpi = std::make_unique<MpiQueue>();  // throws when built without MPI
      if (mpi->size() >= 2) options.mpi = mpi.get();
    }
    if (options.mpi && options.mpi->rank() != 0) {
      serveBoundaryRounds(options);
      return;
    }
    BoundaryResult result;
    try {
      SweepBoundaryRunner runner(options);
      result = runBoundary(spec, runner, args->out);
    } catch (...) {
      if (options.mpi) releaseBoundaryWorkers(*options.mpi);  // stopped: the workers leave too
      throw;
    }
    if (options.mpi) releaseBoundaryWorkers(*options.mpi);
    mpi.reset();  // MPI ends here, before an exit that would skip it
    std::fputs(boundaryLines(spec, result).c_str(), stdout);
    std::printf("results in %s/boundary.json and boundary.csv\n", args->out.c_str());
    bool failed = false;
    for (const BoundaryCaseOutcome& o : result.outcomes) failed = failed || !o.ok;
    std::fflush(nullptr);
    if (failed) std::exit(1);
  });
}

}  // namespace wiggle::cli
