// `wiggle run [CONFIG.toml] [--set section.key=value]... [--out DIR] [--threads N] [--resume]`
#include <cstdio>
#include <filesystem>
#include <optional>

#include "Commands.h"
#include "PathChecks.h"
#include "core/Error.h"
#include "io/AtomicFile.h"
#include "io/Config.h"
#include "scenario/Experiment.h"

namespace wiggle::cli {

namespace {

struct RunArgs {
  std::string config;
  std::vector<std::string> sets;
  std::string out = "wiggle-out";
  int threads = 0;
  bool resume = false;
  bool noPlot = false;
};

}  // namespace

void addRunCommand(CLI::App& app) {
  auto args = std::make_shared<RunArgs>();
  auto* cmd = app.add_subcommand("run", "Run one case: make (or reuse) the bed, wiggle the intruder, measure");
  cmd->add_option("config", args->config, "Run config (TOML); none = the embedded default case");
  cmd->add_option("--set", args->sets, "Override a key: --set drive.period=2 (repeatable)")->allow_extra_args(false);
  cmd->add_option("--out", args->out, "Output directory (made if missing; its parent must exist)")->capture_default_str();
  cmd->add_option("--threads", args->threads, "OpenMP threads (default: all cores)")->check(CLI::Range(1, 1024));
  cmd->add_flag("--resume", args->resume, "Continue from the newest good checkpoint in --out");
  cmd->add_flag("--no-plot", args->noPlot, "Do not draw the figures at the end");
  cmd->footer("Config keys (TOML section.key, default, unit):\n" + configHelp());
  cmd->callback([args] {
    std::optional<std::string> path;
    if (!args->config.empty()) path = args->config;
    // Resuming without a config reuses the run directory's own resolved config.
    const std::string saved = args->out + "/config.toml";
    if (!path && args->resume && std::filesystem::exists(saved)) path = saved;
    if (path) requireInputFile(*path, "config file");
    requireOutputDirectory("--out", args->out);
    const RunConfig config = loadRunConfig(path, args->sets);
    RunOptions options;
    options.outDir = args->out;
    options.threads = args->threads;
    options.resume = args->resume;
    const RunOutcome outcome = runExperiment(config, options);
    std::printf("V_y = %.6g (least-squares slope %.6g) d per sqrt(d/g); summary in %s\n", outcome.vy,
                outcome.vySlope, outcome.summaryPath.c_str());
    for (const std::string& w : outcome.warnings) std::fprintf(stderr, "wiggle: warning: %s\n", w.c_str());
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
