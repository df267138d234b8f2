// `wiggle run [CONFIG.toml] [--set section.key=value]... [--out DIR] [--threads N] [--resume]`
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>

#include "Commands.h"
#include "PathChecks.h"
#include "core/Error.h"
#include "core/Format.h"
#include "core/Machine.h"
#include "io/AtomicFile.h"
#include "io/Config.h"
#include "physics/ForceKernels.h"
#include "scenario/bed/BedMaker.h"
#include "scenario/cost/CostModel.h"
#include "scenario/run/BedScatter.h"
#include "scenario/run/Checkpoint.h"
#include "scenario/run/Experiment.h"

namespace wiggle::cli {

namespace {

struct RunArgs {
  std::string config;
  std::vector<std::string> sets;
  std::string out = "wiggle-out";
  int threads = 0;
  bool fixedThreads = false;
  bool resume = false;
  bool noPlot = false;
  bool check = false;
};

// `run --check`: everything `wiggle run` checks before it starts (the config, the outline, the
// clump, the geometry, the output directory), then what the run would be, without running it.
void printCheck(const RunConfig& c, const std::string& out, bool resume, int threads) {
  const Case run = prepareCase(c);
  const ClumpDef& clump = run.clump;
  const SpeedBasis speed = speedBasis(c);
  const double ns = speed.ns;
  const std::uint64_t steps = run.steps.total;
  std::printf("config ok: %s intruder at y0 = %g (%g d below the surface), A = %g, T = %g, mu = %g\n",
              std::string(choiceName(c.intruder.shape)).c_str(), c.intruder.y0, c.box.bedHeight - c.intruder.y0,
              c.drive.amplitude, c.drive.period, c.contact.mu);
  std::printf("bed: %g x %g d, about %.0f grains (estimate), %zu intruder atoms, mass %g", c.box.width,
              c.box.bedHeight, estimatedGrains(c), clump.offsetX.size(), clump.mass);
  if (clump.massShares == 1)
    std::printf("\n");
  else  // intruder.contact_mass = "atom" (docs/PHYSICS.md, section 6)
    std::printf(", in its contacts' meff %g (M / %u: one of the glued spheres filling it)\n", clump.contactMass(),
                clump.massShares);
  const BedPlan bed = planBed(c, clump);
  switch (bed.source) {
    case BedPlan::Source::File:
      std::printf("bed: bed.file = %s (%s)\n", bed.path.c_str(),
                  std::filesystem::is_regular_file(bed.path) ? "checked when the run starts" : "no such file");
      break;
    case BedPlan::Source::Cached: std::printf("bed %s: cached (%s)\n", bed.key.c_str(), bed.path.c_str()); break;
    case BedPlan::Source::Carve:
      std::printf("bed %s: not cached; carved from base bed %s (%s), about %s on one core (estimate)\n",
                  bed.key.c_str(), bed.baseKey.c_str(), bed.baseCached ? "cached" : "not cached: poured first",
                  formatDuration(estimatedBedSeconds(c, ns, !bed.baseCached)).c_str());
      break;
    case BedPlan::Source::Pour:
      std::printf("bed %s: not cached, making it takes about %s on one core (estimate)\n", bed.key.c_str(),
                  formatDuration(estimatedBedSeconds(c, ns)).c_str());
      break;
  }
  std::printf("run: %llu steps (t = %g at dt = %g), about %s on one core at %.3g ns per particle-step (%s)\n",
              static_cast<unsigned long long>(steps), c.run.duration, c.run.dt,
              formatDuration(estimatedRunSeconds(c, ns)).c_str(), ns, speed.source.c_str());
  if (threads > 1) {
    const ThreadScaling scaling = threadScaling(estimatedParticles(c), threads);
    std::printf("at %d threads: about %s (%s)\n", threads,
                formatDuration(estimatedRunSeconds(c, ns) / scaling.speedUp).c_str(), scaling.words.c_str());
  }
  const bool finished = std::filesystem::exists(out + "/summary.json");
  const bool started = std::filesystem::exists(checkpointPath(out));
  std::printf("out: %s (%s)\n", out.c_str(),
              finished  ? (resume ? "holds a finished run: --resume would only rewrite its results"
                                  : "holds a finished run: wiggle run would refuse it without --resume")
              : started ? (resume ? "holds a checkpoint: --resume continues it" : "holds a checkpoint: add --resume")
              : holdsRun(out) ? "holds a run stopped before its first checkpoint: it would start again from its bed"
                              : "new");
}

}  // namespace

void addRunCommand(CLI::App& app) {
  auto args = std::make_shared<RunArgs>();
  auto* cmd = app.add_subcommand("run", "Run one case: make (or reuse) the bed, wiggle the intruder, measure");
  cmd->add_option("config", args->config, "Run config (TOML); none = the embedded default case");
  cmd->add_option("--set", args->sets, "Override a key: --set drive.period=2 (repeatable)")->allow_extra_args(false);
  cmd->add_option("--out", args->out, "Output directory (made if missing; its parent must exist)")->capture_default_str();
  cmd->add_option("--threads", args->threads,
                  "OpenMP threads (default: the cores other work leaves idle, by the 1-minute load average; at least 1)")
      ->check(CLI::Range(1, 1024));
  cmd->add_flag("--fixed-threads", args->fixedThreads,
                "Step on all the --threads always, even while another process holds a core (by default a run sheds "
                "threads that only wait for each other and takes them back when the core is free: the same bits); "
                "for benchmarks of a thread count");
  cmd->add_flag("--resume", args->resume,
                "Continue the run in --out from its newest good checkpoint (a finished run: extended or rewritten); "
                "refused when --out holds no run");
  cmd->add_flag("--no-plot", args->noPlot, "Do not draw the figures at the end");
  cmd->add_flag("--check", args->check,
                "Check the config and print what the run would be (grains, steps, bed cached or not, "
                "estimated cost); run nothing, write nothing");
  cmd->footer(
      "Exit status: 0 done, 2 bad input (one line names the problem), 130 or 143 when SIGINT (Ctrl-C) or\n"
      "SIGTERM stopped it after a checkpoint (continue with --resume), 3 an internal error.\n\n"
      "Config keys (TOML section.key, default, unit):\n" +
      configHelp());
  cmd->callback([args] {
    defaultSimdLevel();  // a bad WIGGLE_SIMD is bad input before anything is written
    std::optional<std::string> path;
    if (!args->config.empty()) path = args->config;
    // Resuming without a config reuses the run directory's own resolved config.
    const std::string saved = args->out + "/config.toml";
    if (!path && args->resume && std::filesystem::exists(saved)) path = saved;
    if (path) requireInputFile(*path, "config file");
    requireOutputDirectory("--out", args->out);
    // A mistyped --out must not start hours of a run nobody asked for.
    if (args->resume && !holdsRun(args->out))
      throw Error("--resume: " + args->out +
                  " holds no run to continue (no checkpoint, no finished run, no run started there); "
                  "leave out --resume to start a new run there");
    const RunConfig config = loadRunConfig(path, args->sets);
    if (args->check) {
      requireWritableOutputDirectory("--out", args->out);
      printCheck(config, args->out, args->resume, args->threads > 0 ? args->threads : idleCores());
      return;
    }
    RunOptions options;
    options.outDir = args->out;
    options.threads = args->threads > 0 ? args->threads : idleCores();
    if (args->threads == 0 && options.threads < availableCores())
      std::fprintf(stderr, "wiggle: the machine is busy (1-minute load average %.1f on %d cores): %d thread%s; "
                   "--threads N to choose\n", loadAverage(), availableCores(), options.threads,
                   options.threads == 1 ? "" : "s");
    options.resume = args->resume;
    if (args->fixedThreads) options.threadPolicy = ThreadPolicy::Fixed;
    const RunOutcome outcome = runExperiment(prepareCase(config), options);
    std::printf("%s\n", outcome.resultLine().c_str());
    // What the number is worth: one bed, and the scatter between beds where a study measured it.
    std::printf("%s\n", oneBedScatterNote(config, outcome.summary.tInitial, outcome.summary.tFinal).c_str());
    for (const std::string& w : outcome.summary.warnings) std::fprintf(stderr, "wiggle: warning: %s\n", w.c_str());
    if (const std::string shed = threadsShedWarning(outcome.summary); !shed.empty())
      std::fprintf(stderr, "wiggle: warning: %s\n", shed.c_str());
    std::fflush(stdout);  // before the plotter writes to the same stream
    if (config.run.plot && !args->noPlot) {
      int status = 1;
      try {
        status = runPlotter({args->out});
      } catch (const Error& e) {
        std::fprintf(stderr, "wiggle: %s\n", e.what());
      }
      if (status != 0)
        std::fprintf(stderr, "wiggle: warning: the figures could not be drawn (see above); the results are complete\n");
    }
  });
}

}  // namespace wiggle::cli
