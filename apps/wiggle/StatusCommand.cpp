// `wiggle status DIR`: a sweep directory at a glance (sweep/SweepStatus.h).
#include <cstdio>

#include "Commands.h"
#include "sweep/SweepStatus.h"

namespace wiggle::cli {

void addStatusCommand(CLI::App& app) {
  auto dir = std::make_shared<std::string>();
  auto* cmd = app.add_subcommand("status", "A sweep directory at a glance: cases done, running, failed, pending, and time to go");
  cmd->add_option("dir", *dir, "Sweep directory (wiggle sweep --out DIR)")->required();
  cmd->callback([dir] { std::fputs(formatSweepStatus(readSweepStatus(*dir)).c_str(), stdout); });
}

}  // namespace wiggle::cli
