// `wiggle status DIR`: a sweep directory or a single run's directory at a glance
// (sweep/SweepStatus.h).
#include <cstdio>
#include <filesystem>
#include <optional>

#include "Commands.h"
#include "core/Error.h"
#include "sweep/SweepStatus.h"

namespace wiggle::cli {

void addStatusCommand(CLI::App& app) {
  auto dir = std::make_shared<std::string>();
  auto* cmd = app.add_subcommand(
      "status",
      "A sweep directory at a glance (cases done, running, failed, pending, and time to go), or a run's "
      "directory (done, running, interrupted at t or failed)");
  cmd->add_option("dir", *dir, "Sweep directory (wiggle sweep --out DIR) or run directory (wiggle run --out DIR)")
      ->required();
  cmd->callback([dir] {
    // A sweep directory has results.csv; a run directory what scenario/Experiment.h's holdsRun names.
    if (!std::filesystem::exists(*dir + "/results.csv")) {
      if (const std::optional<RunDirStatus> run = readRunDirStatus(*dir)) {
        std::fputs(formatRunDirStatus(*run).c_str(), stdout);
        return;
      }
      if (std::filesystem::is_directory(*dir))
        throw Error(*dir +
                    ": neither a sweep directory (no results.csv) nor a run directory (no progress.json, "
                    "checkpoint or summary.json)");
    }
    std::fputs(formatSweepStatus(readSweepStatus(*dir)).c_str(), stdout);
  });
}

}  // namespace wiggle::cli
