// `wiggle export-lammps [CONFIG.toml] [--set section.key=value]... --out DIR [--threads N]`
// Writes DIR/data.lammps and DIR/in.wiggle: the case `wiggle run` would run, from the same bed
// (docs/LAMMPS-EXPORT.md).
#include <omp.h>

#include <cstdio>
#include <optional>

#include "Commands.h"
#include "PathChecks.h"
#include "core/Console.h"
#include "core/Error.h"
#include "core/Machine.h"
#include "core/StopSignal.h"
#include "io/Config.h"
#include "physics/ForceKernels.h"
#include "scenario/case/Case.h"
#include "scenario/lammps/LammpsExport.h"
#include "scenario/run/Experiment.h"

namespace wiggle::cli {

namespace {

struct ExportArgs {
  std::string config;
  std::vector<std::string> sets;
  std::string out;
  int threads = 0;
};

// The case's start as `wiggle run` makes it (startRun: the bed cached or made now, the drive
// started), with the bed's progress on stderr: on a terminal a rewritten status line; otherwise (a
// log, a benchmark script) a line every 30 s, so that a bed that takes an hour shows that it is
// getting on.
CachedBed startExport(const Case& run) {
  ProgressLine progress(
      true,
      [&](const std::string& text) {
        if (!progress.onTerminal()) std::fprintf(stderr, "%s\n", text.c_str());
      },
      30.0);
  const StopSignalGuard stopOnSignal;  // SIGINT/SIGTERM while the bed is made: save it, then stop
  CachedBed bed =
      startRun(run, [&](const BedStatus& st) { progress.update(bedStatusLine(st, run.config.box.bedHeight)); });
  progress.clear();
  if (!bed.note.empty()) std::fprintf(stderr, "wiggle: warning: %s\n", bed.note.c_str());
  return bed;
}

}  // namespace

void addExportLammpsCommand(CLI::App& app) {
  auto args = std::make_shared<ExportArgs>();
  auto* cmd = app.add_subcommand(
      "export-lammps", "Write the case as a LAMMPS data file and deck (same bed as `wiggle run`, made if not cached)");
  cmd->add_option("config", args->config, "Run config (TOML); none = the embedded default case");
  cmd->add_option("--set", args->sets, "Override a key: --set drive.period=2 (repeatable)")->allow_extra_args(false);
  cmd->add_option("--out", args->out,
                  "Output directory (gets data.lammps and in.wiggle; made if missing, its parent must exist)")
      ->required();
  cmd->add_option("--threads", args->threads,
                  "OpenMP threads for making the bed (default: the cores other work leaves idle, by the 1-minute "
                  "load average; at least 1)")
      ->check(CLI::Range(1, 1024));
  cmd->footer(
      "Run the deck with:  cd DIR && lmp -in in.wiggle   (or mpirun -np 2 lmp -in in.wiggle; -var nsteps N "
      "to shorten it).\nLAMMPS writes the intruder's t,x,y,vx,vy,fy to DIR/trajectory.csv. Contact history "
      "cannot be carried into a data file: LAMMPS starts every contact with zero shear.");
  cmd->callback([args] {
    defaultSimdLevel();  // a bad WIGGLE_SIMD is bad input before anything is written
    omp_set_num_threads(args->threads > 0 ? args->threads : idleCores());
    std::optional<std::string> path;
    if (!args->config.empty()) path = args->config;
    if (path) requireInputFile(*path, "config file");
    requireOutputDirectory("--out", args->out);
    const Case run = prepareCase(loadRunConfig(path, args->sets));
    const CachedBed bed = startExport(run);
    const LammpsDeck deck = exportLammps(bed.world, run, args->out);
    std::printf("bed %s %s\n", bed.fromCache ? "loaded from" : "made and cached at", bed.path.c_str());
    std::printf("wrote %s/%s and %s/%s: %llu atoms (%u grains), %llu steps\n", args->out.c_str(), kLammpsDataFile,
                args->out.c_str(), kLammpsInputFile, static_cast<unsigned long long>(deck.atoms), deck.grains,
                static_cast<unsigned long long>(deck.steps));
    std::printf("run it with: cd %s && lmp -in %s\n", args->out.c_str(), kLammpsInputFile);
  });
}

}  // namespace wiggle::cli
