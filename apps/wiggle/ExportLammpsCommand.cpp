// `wiggle export-lammps [CONFIG.toml] [--set section.key=value]... --out DIR [--threads N]`
// Writes DIR/data.lammps and DIR/in.wiggle: the case `wiggle run` would run, from the same bed
// (docs/LAMMPS-EXPORT.md).
#include <omp.h>

#include <cstdio>
#include <optional>

#include "Commands.h"
#include "PathChecks.h"
#include "core/Error.h"
#include "physics/ForceKernels.h"
#include "core/Machine.h"
#include "io/Config.h"
#include "scenario/case/Case.h"
#include "scenario/lammps/LammpsExport.h"

namespace wiggle::cli {

namespace {

struct ExportArgs {
  std::string config;
  std::vector<std::string> sets;
  std::string out;
  int threads = 0;
};

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
    const RunConfig config = loadRunConfig(path, args->sets);
    const LammpsExportResult r = exportLammps(prepareCase(config), args->out);
    std::printf("bed %s %s\n", r.bedFromCache ? "loaded from" : "made and cached at", r.bedPath.c_str());
    std::printf("wrote %s/%s and %s/%s: %llu atoms (%u grains), %llu steps\n", args->out.c_str(), kLammpsDataFile,
                args->out.c_str(), kLammpsInputFile, static_cast<unsigned long long>(r.deck.atoms), r.deck.grains,
                static_cast<unsigned long long>(r.deck.steps));
    std::printf("run it with: cd %s && lmp -in %s\n", args->out.c_str(), kLammpsInputFile);
  });
}

}  // namespace wiggle::cli
