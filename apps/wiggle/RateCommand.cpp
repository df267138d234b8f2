// `wiggle rate DIR [--from T0] [--to T1] [--band D] [--write]`: V_y measured again, by both rules
// (analysis/RiseRate.h), from the trajectory.csv of a run or of every finished case of a sweep
// directory, over the run's own window or any other (a trajectory shorter than its run, as a short
// LAMMPS run of an exported deck or a run still going, to its end, said on stderr); a CSV table on stdout. --write records
// the settle rule's result (vy_settled, t_settled) in summary.json files written before it existed,
// and in the sweep's results.csv (scenario/run/Remeasure.h).
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "Commands.h"
#include "core/Error.h"
#include "core/Format.h"
#include "scenario/run/Remeasure.h"
#include "sweep/ResultsTable.h"

namespace wiggle::cli {

namespace fs = std::filesystem;

namespace {

// The run directories under DIR: DIR itself when it is a run (it has a config.toml), else every
// case of DIR/cases that has finished (caseFinished: its summary.json says ok; a case still running
// has a trajectory.csv of its steps so far), by name; `pending` counts the others.
std::vector<std::string> runDirectories(const std::string& dir, bool& isSweep, int& pending) {
  if (!fs::is_directory(dir)) throw Error(dir + ": no such directory");
  isSweep = false;
  pending = 0;
  if (fs::is_regular_file(dir + "/config.toml")) return {dir};
  if (!fs::is_directory(dir + "/cases"))
    throw Error(dir + " is neither a run directory (config.toml) nor a sweep directory (cases/)");
  isSweep = true;
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir + "/cases")) {
    if (!entry.is_directory()) continue;
    if (caseFinished(entry.path().string()))
      names.push_back(entry.path().filename().string());
    else
      ++pending;
  }
  std::sort(names.begin(), names.end());
  std::vector<std::string> dirs;
  for (const std::string& name : names) dirs.push_back(dir + "/cases/" + name);
  return dirs;
}

std::string row(const std::string& name, const Remeasured& r) {
  auto number = [](double v) { return formatNumber(v, 10); };
  return csvCell(name) + ',' + number(r.period) + ',' + number(r.rate.tInitial) + ',' + number(r.rate.tFinal) + ',' +
         number(r.rate.vy) + ',' + (r.rate.plateau ? "true" : "false") + ',' + number(r.settled.tSettled) + ',' +
         number(r.settled.vy) + ',' + (r.settled.settled ? "true" : "false") + '\n';
}

}  // namespace

void addRateCommand(CLI::App& app) {
  struct Options {
    std::string dir;
    std::optional<double> from, to;
    double band = SettleRule{}.band;
    bool write = false;
  };
  auto opts = std::make_shared<Options>();
  auto* cmd = app.add_subcommand(
      "rate",
      "V_y again from trajectory.csv, by the run's rule and by the paper's t_f rule (vy_settled), over the "
      "run's window or another, for a run or every finished case of a sweep: a CSV table on stdout");
  cmd->add_option("dir", opts->dir, "A run directory (wiggle run --out DIR) or a sweep directory")->required();
  cmd->add_option("--from", opts->from, "t_i: start of the window [sqrt(d/g)] (default 0.1 x the window's end)");
  cmd->add_option("--to", opts->to,
                  "end of the data used, as if the run had ended there [sqrt(d/g)] (default the run's end)");
  cmd->add_option("--band", opts->band,
                  "the settle rule's band: how close to its final level the intruder must stay [d] (default " +
                      formatNumber(SettleRule{}.band) + ")");
  cmd->add_flag("--write", opts->write,
                "record vy_settled and t_settled (the run's own window and band) in each summary.json and in "
                "the sweep's results.csv");
  cmd->callback([opts] {
    RemeasureRequest request;
    request.from = opts->from;
    request.to = opts->to;
    request.rule.band = opts->band;
    if (!(opts->band > 0)) throw Error("--band must be positive (it is " + formatNumber(opts->band) + ")");
    if (opts->write && !request.isRunsOwn())
      throw Error("--write records the run's own window and band only: drop --from, --to and --band");
    bool isSweep = false;
    int pending = 0;
    const std::vector<std::string> dirs = runDirectories(opts->dir, isSweep, pending);
    // Everything is measured before anything is written: a bad case leaves every file as it was.
    std::vector<Remeasured> measured;
    for (const std::string& dir : dirs) measured.push_back(remeasureRun(dir, request));
    std::string table = "run,period,t_i,t_f,vy,plateau,t_settled,vy_settled,settled\n";
    for (std::size_t k = 0; k < dirs.size(); ++k)
      table += row(isSweep ? fs::path(dirs[k]).filename().string() : dirs[k], measured[k]);
    std::fputs(table.c_str(), stdout);
    for (std::size_t k = 0; k < dirs.size(); ++k)
      if (measured[k].cutShortAt > 0)
        std::fprintf(stderr,
                     "wiggle rate: %s: trajectory.csv ends at t = %s, before the config's run.duration (a shorter "
                     "run, or one not finished): measured what there is, t = %s to %s\n",
                     dirs[k].c_str(), formatNumber(measured[k].cutShortAt).c_str(),
                     formatNumber(measured[k].rate.tInitial).c_str(), formatNumber(measured[k].rate.tFinal).c_str());
    for (std::size_t k = 0; k < dirs.size(); ++k)
      for (const std::string& warning : rateWarnings(measured[k].rate))
        std::fprintf(stderr, "wiggle rate: warning: %s: %s\n", dirs[k].c_str(), warning.c_str());
    // Each row is one bed's V_y: what that is worth, once per distinct note (a sweep's cases mostly
    // share one); a sweep's cells.csv has the cells' means and standard errors.
    std::vector<std::string> notes;
    for (const Remeasured& m : measured)
      if (std::find(notes.begin(), notes.end(), m.scatterNote) == notes.end()) notes.push_back(m.scatterNote);
    for (const std::string& note : notes)
      std::fprintf(stderr, "wiggle rate: %s%s\n", isSweep ? "each row is " : "", note.c_str());
    if (isSweep)
      std::fprintf(stderr,
                   "wiggle rate: %s/cells.csv pools each cell's beds over the run's own window (wiggle status)\n",
                   opts->dir.c_str());
    if (pending)
      std::fprintf(stderr, "wiggle rate: %d case%s not finished left out\n", pending,
                   pending == 1 ? "" : "s");
    if (!opts->write) return;
    for (std::size_t k = 0; k < dirs.size(); ++k) recordSettled(dirs[k], measured[k].settled, request.rule);
    if (isSweep && fs::is_regular_file(opts->dir + "/results.csv")) refreshSettledColumns(opts->dir);
    std::fprintf(stderr, "wiggle rate: recorded vy_settled in %zu summary.json file%s%s\n", dirs.size(),
                 dirs.size() == 1 ? "" : "s", isSweep ? " and results.csv" : "");
  });
}

}  // namespace wiggle::cli
