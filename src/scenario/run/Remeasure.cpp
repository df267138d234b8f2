#include "scenario/run/Remeasure.h"

#include <filesystem>
#include <nlohmann/json.hpp>

#include "core/Error.h"
#include "core/Format.h"
#include "io/AtomicFile.h"
#include "io/Config.h"
#include "scenario/case/Case.h"
#include "scenario/run/BedScatter.h"

namespace wiggle {

RunRates measureRunRates(const Case& run, const std::vector<TrajectorySample>& samples, RateWindow window,
                         const SettleRule& rule) {
  const double period = run.config.drive.period;
  const RiseRate rate = measureRiseRate(samples, window, period, run.surfacedHeight);
  return {rate, measureSettledRate(samples, window, period, rate, rule)};
}

Remeasured remeasureRun(const std::string& runDir, const RemeasureRequest& request) {
  const std::string configPath = runDir + "/config.toml";
  const std::string trajectoryPath = runDir + "/trajectory.csv";
  if (!std::filesystem::is_regular_file(configPath)) throw Error(runDir + ": no config.toml: not a run directory");
  if (!std::filesystem::is_regular_file(trajectoryPath))
    throw Error(runDir + ": no trajectory.csv: the run has neither finished nor written a checkpoint");
  // The case, for its surfaced height (the plateau rule) as the run worked it out.
  const Case run = prepareCase(parseRunConfig(readFile(configPath), configPath), BedNeeded::No);
  const std::vector<TrajectorySample> samples = readTrajectoryCsv(trajectoryPath);

  Remeasured r;
  r.period = run.config.drive.period;
  const double end = samples.back().t;
  const double tolerance = 1e-9 * std::max(1.0, end);
  RateWindow window;
  window.to = request.to.value_or(run.config.run.duration);
  if (!request.to && window.to > end + tolerance) {
    window.to = end;
    r.cutShortAt = end;
  }
  window.from = request.from.value_or(paperWindow(window.to).from);
  if (window.to > end + tolerance)
    throw Error("--to " + formatNumber(window.to) + " is past the end of " + trajectoryPath +
                " (t = " + formatNumber(end) + ")");
  if (window.from < samples.front().t)
    throw Error("--from " + formatNumber(window.from) + " is before the start of " + trajectoryPath);
  const RunRates rates = measureRunRates(run, samples, window, request.rule);
  r.rate = rates.rate;
  r.settled = rates.settled;
  r.scatterNote = oneBedScatterNote(run.config, r.rate.tInitial, r.rate.tFinal);
  return r;
}

void recordSettled(const std::string& runDir, const SettledRate& settled, const SettleRule& rule) {
  const std::string path = runDir + "/summary.json";
  if (!std::filesystem::is_regular_file(path)) throw Error(runDir + ": no summary.json: the run has not finished");
  nlohmann::json summary;
  try {
    summary = nlohmann::json::parse(readFile(path));
  } catch (const nlohmann::json::exception& e) {
    throw Error(path + " is not valid JSON: " + e.what());
  }
  if (!summary.is_object()) throw Error(path + ": expected a JSON object");
  // Unsettled, the rule reports the run's own vy and t_f: those in the file, not their values
  // recomputed from trajectory.csv's 10 digits, so that the two columns are equal to the bit.
  const bool own = !settled.settled && summary.contains("vy") && summary.contains("t_f");
  summary["vy_settled"] = own ? summary["vy"] : nlohmann::json(settled.vy);
  summary["t_settled"] = own ? summary["t_f"] : nlohmann::json(settled.tSettled);
  summary["settled"] = settled.settled;
  summary["settle_band"] = rule.band;
  writeFileAtomically(path, summary.dump(2) + "\n");
}

}  // namespace wiggle
