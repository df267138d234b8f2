// `wiggle sweep SWEEP.toml [--out DIR] [--jobs N] [--threads T] [--dry-run] [--case K]`, also under
// `mpirun -np N wiggle sweep ...` (docs/SWEEPS.md). The hidden `--run-case CONFIG.toml --out DIR`
// and `--make-bed CONFIG.toml` are the tasks the sweep runs in child processes.
#include <cstdio>
#include <cstdlib>
#include <memory>

#include "Commands.h"
#include "PathChecks.h"
#include "core/Error.h"
#include "physics/ForceKernels.h"
#include "sweep/SweepRunner.h"
#include "sweep/TaskRunner.h"

namespace wiggle::cli {

namespace {

struct SweepArgs {
  std::string file;
  std::string out;
  int jobs = 0;
  int threads = 0;
  bool dryRun = false;
  bool local = false;
  std::string onlyCase;
  std::string makeBed;
  std::string runCase;
};

}  // namespace

void addSweepCommand(CLI::App& app) {
  auto args = std::make_shared<SweepArgs>();
  auto* cmd = app.add_subcommand("sweep", "Run every case of a sweep file (locally, or under mpirun/srun), resumably");
  cmd->add_option("sweep", args->file, "Sweep file (TOML: [sweep], [base], [grid], [[case]]; docs/CONFIG.md)");
  cmd->add_option("--out", args->out,
                  "Sweep directory (default: sweep-<sweep name>; made if missing, its parent must exist)");
  cmd->add_option("--jobs", args->jobs,
                  "Cases at once (default: sweep.jobs, else one per core); under MPI: per worker rank (default 1)")
      ->check(CLI::Range(1, 100000));
  cmd->add_option("--threads", args->threads,
                  "Threads per case (default: sweep.threads_per_case, else cores / jobs)")
      ->check(CLI::Range(1, 1024));
  cmd->add_flag("--dry-run", args->dryRun, "List the cases and the estimated cost; run nothing");
  cmd->add_flag("--local", args->local, "Ignore an MPI launcher: run every case from this process");
  cmd->add_option("--case", args->onlyCase,
                  "Run only this case (its number from 1, or its name, as --dry-run lists them), its bed first if "
                  "need be: one Slurm array task (--array=1-N, --case $SLURM_ARRAY_TASK_ID); results.csv merges all cases");
  // The one entry through which a sweep runs its tasks in child processes (sweep/TaskRunner.h).
  cmd->add_option(kBedTaskFlag, args->makeBed, "(internal) make and cache the bed of a run config")->group("");
  cmd->add_option(kCaseTaskFlag, args->runCase, "(internal) run a case's config into --out, resuming")->group("");
  cmd->footer(
      "Each case runs in DIR/cases/<case name>/ as `wiggle run ... --resume`; DIR/results.csv is rewritten after\n"
      "every case, DIR/sweep.log records what happened. Run the same command again to resume: finished cases\n"
      "are skipped, interrupted ones continue from their checkpoints, failed ones are retried.\n"
      "Exit status: 0 when every case is ok, 1 when some failed or did not finish, 2 for bad input, 130 or 143\n"
      "when SIGINT or SIGTERM stopped it (its cases checkpointed: run the same command to resume).");
  cmd->callback([args] {
    defaultSimdLevel();  // a bad WIGGLE_SIMD is bad input before anything is written
    if (!args->makeBed.empty()) {
      requireInputFile(args->makeBed, "config file");
      makeSweepBed(args->makeBed, args->threads);
      return;
    }
    if (!args->runCase.empty()) {
      requireInputFile(args->runCase, "config file");
      if (args->out.empty()) throw Error(std::string(kCaseTaskFlag) + " needs --out (the case's run directory)");
      runSweepCase(args->runCase, args->out, args->threads);
      return;
    }
    if (args->file.empty()) throw Error("sweep: no sweep file given (wiggle sweep SWEEP.toml)");
    requireInputFile(args->file, "sweep file");
    requireOutputDirectory("--out", args->out);  // the default, sweep-<name>, is in the current directory
    SweepOptions options;
    options.outDir = args->out;
    options.jobs = args->jobs;
    options.threads = args->threads;
    options.dryRun = args->dryRun;
    options.allowMpi = !args->local;
    options.onlyCase = args->onlyCase;
    options.summaryAsEvent = false;  // printed below, once
    const SweepOutcome outcome = runSweep(args->file, options);
    if (outcome.worker || args->dryRun) return;
    if (outcome.interrupted) throw Interrupted(outcome.stopSignal, outcome.summary);
    if (outcome.failed || outcome.pending) {
      std::fprintf(stderr, "wiggle: %s\n", outcome.summary.c_str());
      std::fflush(nullptr);
      std::exit(1);
    }
    std::printf("%s; results in %s/results.csv\n", outcome.summary.c_str(), outcome.outDir.c_str());
  });
}

}  // namespace wiggle::cli
