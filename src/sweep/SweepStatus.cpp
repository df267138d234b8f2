#include "sweep/SweepStatus.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string_view>

#include "core/Error.h"
#include "core/Format.h"
#include "core/Median.h"
#include "io/AtomicFile.h"
#include "io/Config.h"
#include "io/FileLock.h"
#include "scenario/bed/BedMaker.h"
#include "scenario/run/Experiment.h"
#include "scenario/run/RunProgress.h"
#include "sweep/ResultsTable.h"
#include "sweep/SweepStart.h"
#include "sweep/TaskRunner.h"

namespace wiggle {

namespace fs = std::filesystem;

namespace {

double number(const std::string& cell) {
  try {
    return cell.empty() ? 0.0 : std::stod(cell);
  } catch (const std::exception&) {
    return 0.0;
  }
}

// The beds under `dir`/beds that are not made yet: being made now (a process holds the cache's
// bed-KEY.lock) or stopped. A bed is made when its log holds the maker's last line
// (bedTaskDoneLine), or the cache holds it. The cache is the one this process's config and
// environment name ($WIGGLE_CACHE), as for the sweep that shares them. A bed whose config cannot be
// read (another wiggle's) is left out: where its cache is cannot be known.
std::vector<BedAtAGlance> unfinishedBeds(const std::string& dir) {
  std::vector<BedAtAGlance> beds;
  std::error_code ec;
  for (const fs::directory_entry& e : fs::directory_iterator(dir + "/beds", ec)) {
    const std::string file = e.path().filename().string();
    if (e.path().extension() != ".toml" || file.rfind("bed-", 0) != 0) continue;
    BedAtAGlance bed;
    bed.key = file.substr(4, file.size() - 4 - 5);
    RunConfig config;
    try {
      config = parseRunConfig(readFile(e.path().string()), e.path().string());
    } catch (const Error&) {
      continue;
    }
    bool made = fs::exists(bedCachePath(config, bed.key));
    const std::string log = dir + "/beds/bed-" + bed.key + ".log";
    if (fs::exists(log)) {
      std::istringstream lines(readFile(log));
      for (std::string line; std::getline(lines, line);) {
        if (line.rfind("[bed]", 0) == 0) bed.report = line;
        made = made || isBedTaskDoneLine(line, bed.key);
      }
    }
    if (made) continue;
    if (FileLock::holders(bedLockPath(config, bed.key)) != FileLock::Holders::None)
      bed.state = BedAtAGlance::State::Making;
    else if (fs::exists(bedPartialPath(config, bed.key)))
      bed.state = BedAtAGlance::State::PartMade;
    beds.push_back(std::move(bed));
  }
  std::sort(beds.begin(), beds.end(), [](const BedAtAGlance& a, const BedAtAGlance& b) { return a.key < b.key; });
  return beds;
}

// DIR/cells.csv's rows (sweep/CellTable.h); none when the sweep wrote no such file (an older wiggle).
std::vector<CellAtAGlance> readCells(const std::string& dir) {
  const std::string path = dir + "/cells.csv";
  std::vector<CellAtAGlance> cells;
  if (!fs::exists(path)) return cells;
  const auto rows = parseCsv(readFile(path));
  if (rows.empty()) throw Error(path + ": empty");
  const std::vector<std::string>& header = rows.front();
  auto column = [&](const char* name) {
    const auto it = std::find(header.begin(), header.end(), name);
    if (it == header.end()) throw Error(path + ": no column '" + name + "'");
    return static_cast<std::size_t>(it - header.begin());
  };
  const std::size_t nameAt = column("cell"), bedsAt = column("beds"), nAt = column("n"), meanAt = column("vy_mean"),
                    sdAt = column("vy_sd"), seAt = column("vy_se"), verdictAt = column("verdict");
  for (std::size_t r = 1; r < rows.size(); ++r) {
    const auto& row = rows[r];
    if (row.size() < header.size()) throw Error(path + ": row " + std::to_string(r + 1) + " is short");
    CellAtAGlance c;
    c.name = row[nameAt];
    c.beds = static_cast<std::size_t>(number(row[bedsAt]));
    c.stats.n = static_cast<std::size_t>(number(row[nAt]));
    c.stats.mean = number(row[meanAt]);
    c.stats.sd = number(row[sdAt]);
    c.stats.se = number(row[seAt]);
    const std::optional<CellVerdict> verdict = choiceNamed<CellVerdict>(row[verdictAt]);
    if (!verdict)
      throw Error(path + ": row " + std::to_string(r + 1) + ": verdict '" + row[verdictAt] + "' is none of " +
                  joinedNames(choiceNameList<CellVerdict>()));
    c.stats.verdict = *verdict;
    cells.push_back(std::move(c));
  }
  return cells;
}

// "2 beds to make, about 5h10m by the sweep's plan"
std::string bedsToMakeText(const SweepStatus& s) {
  return std::to_string(s.bedsToMake) + " bed" + (s.bedsToMake > 1 ? "s" : "") + " to make, about " +
         formatDuration(s.bedSeconds) + " by the sweep's plan";
}

}  // namespace

SweepStatus readSweepStatus(const std::string& dir) {
  const std::string resultsPath = dir + "/results.csv";
  if (!fs::is_directory(dir)) throw Error(dir + ": not a directory");
  if (!fs::exists(resultsPath)) throw Error(dir + ": no results.csv: not a sweep directory");
  const auto rows = parseCsv(readFile(resultsPath));
  if (rows.empty()) throw Error(resultsPath + ": empty");
  const std::vector<std::string>& header = rows.front();
  auto column = [&](const char* name) {
    const auto it = std::find(header.begin(), header.end(), name);
    if (it == header.end()) throw Error(resultsPath + ": no column '" + name + "'");
    return static_cast<std::size_t>(it - header.begin());
  };
  const std::size_t nameAt = column("case"), dirAt = column("run_dir"), statusAt = column("status"),
                    vyAt = column("vy"), wallAt = column("wall_s"), errorAt = column("error");
  // warnings: added after the first results.csv files; absent in theirs.
  const auto warningsIt = std::find(header.begin(), header.end(), "warnings");
  SweepStatus s;
  s.dir = dir;
  s.sweepLock = FileLock::holders(sweepLockPath(dir));
  if (const std::optional<SweepStart> start = readSweepStart(dir)) {
    s.jobs = start->jobs;
    s.name = start->name;
    s.bedsCounted = start->beds.has_value();
    for (const BedToMake& bed : start->beds.value_or(std::vector<BedToMake>{})) {
      if (fs::exists(bed.cachePath)) continue;
      ++s.bedsToMake;
      s.bedSeconds += bed.estimatedSeconds / std::max(1, start->threads);  // as the dry run: threads scale perfectly
    }
  }
  double casesLeft = 0.0;       // the cases left that no running case's own estimate covers, in cases
  double runningSeconds = 0.0;  // the running cases' own estimates of their time left, summed
  double longestRunning = 0.0;  // and the longest: nothing ends before it
  int running = 0;
  std::vector<double> finishedWall;  // each finished case's wall time
  std::vector<double> runningWhole;  // each running case's whole wall time at its present pace
  for (std::size_t r = 1; r < rows.size(); ++r) {
    const auto& row = rows[r];
    if (row.size() < header.size()) throw Error(resultsPath + ": row " + std::to_string(r + 1) + " is short");
    CaseAtAGlance c;
    c.name = row[nameAt];
    c.status = caseStatusNamed(row[statusAt], resultsPath + ": row " + std::to_string(r + 1));
    c.error = row[errorAt];
    const std::string caseDir = dir + "/" + row[dirAt];
    if (c.status == CaseStatus::Ok && !caseFinished(caseDir)) {  // the sweep would run it again
      c.status = CaseStatus::Pending;
      try {
        c.error = "results.csv says ok, but " + readCaseSummary(caseDir).error;
      } catch (const Error& e) {
        c.error = std::string("results.csv says ok, but ") + e.what();
      }
    }
    // A case whose run holds its directory runs now, whatever results.csv says (a one-case task
    // writes the table only when its case ends).
    const bool runHeld = FileLock::holders(runLockPath(caseDir)) != FileLock::Holders::None;
    if (runHeld && c.status != CaseStatus::Ok) {
      c.status = CaseStatus::Running;
      c.error.clear();
    }
    if (c.status == CaseStatus::Ok) {
      if (warningsIt != header.end() && !row[warningsIt - header.begin()].empty())
        c.warnings = readCaseSummary(caseDir).summary.warnings;
      c.vy = number(row[vyAt]);
      c.wallSeconds = number(row[wallAt]);
      finishedWall.push_back(c.wallSeconds);
    } else if (c.status == CaseStatus::Running) {
      // How far it is: its progress.json, which the run rewrites at each stage and every few seconds.
      const RunProgress progress = readRunProgress(caseDir).value_or(RunProgress{RunPhase::Starting, "starting"});
      c.fraction = progress.fraction;
      c.stage = progress.stage;
      c.threadsNow = threadsNowWords(progress);
      c.warnings = readRunWarnings(caseDir);
      c.interrupted = !runHeld && s.sweepLock != FileLock::Holders::Exclusive;
      running += !c.interrupted;
      if (!c.interrupted && progress.etaSeconds > 0) {
        // Its own pace knows its time left better than other cases' wall times do (they may be other
        // shapes, or have run beside other work).
        c.etaSeconds = progress.etaSeconds;
        runningSeconds += c.etaSeconds;
        longestRunning = std::max(longestRunning, c.etaSeconds);
        if (c.fraction > 0 && c.fraction < 1) runningWhole.push_back(c.etaSeconds / (1.0 - c.fraction));
      } else {
        casesLeft += 1.0 - std::max(0.0, c.fraction);
      }
    } else if (c.status == CaseStatus::Pending) {
      casesLeft += 1.0;
    }
    s.cases.push_back(std::move(c));
  }
  s.beds = unfinishedBeds(dir);
  s.cells = readCells(dir);
  s.casesAtOnce = std::max({1, s.jobs, running});  // array tasks: as many as run now
  if (!finishedWall.empty() || !runningWhole.empty()) {
    s.caseTime = finishedWall.empty() ? SweepStatus::CaseTime::RunningPace : SweepStatus::CaseTime::FinishedCases;
    const double work =
        median(finishedWall.empty() ? runningWhole : finishedWall) * casesLeft + runningSeconds + s.bedSeconds;
    s.etaSeconds = std::max(longestRunning, work / s.casesAtOnce);
  }
  return s;
}

bool SweepStatus::replicated() const {
  return std::any_of(cells.begin(), cells.end(), [](const CellAtAGlance& c) { return c.beds > 1; });
}

std::string formatSweepStatus(const SweepStatus& s) {
  int ok = 0, failed = 0, running = 0, pending = 0;
  bool ownEstimates = false;  // a running case's time left counts as its own estimate says
  for (const CaseAtAGlance& c : s.cases) {
    ownEstimates |= c.status == CaseStatus::Running && c.etaSeconds > 0;
    ok += c.status == CaseStatus::Ok;
    failed += c.status == CaseStatus::Failed;
    running += c.status == CaseStatus::Running;
    pending += c.status == CaseStatus::Pending;
  }
  std::ostringstream out;
  out << "sweep " << s.dir << ": " << s.cases.size() << " cases: " << ok << " done, " << running << " running, "
      << failed << " failed, " << pending << " pending; "
      << (s.sweepLock == FileLock::Holders::Exclusive ? "a wiggle sweep is running in it"
          : s.sweepLock == FileLock::Holders::Shared  ? "one-case `wiggle sweep --case` tasks are running in it"
                                                      : "no wiggle sweep is running in it (run the same `wiggle sweep` "
                                                       "or `wiggle boundary` command to continue)")
      << "\n";
  for (const CaseAtAGlance& c : s.cases) {
    if (c.status == CaseStatus::Running)
      out << "  running  " << c.name
          << (c.fraction < 0 ? " (" + c.stage + ")"
                             : " (" + formatNumber(100.0 * c.fraction, 3) + " % of its run" +
                                   (c.etaSeconds > 0 ? ", about " + formatDuration(c.etaSeconds) + " to go" : "") +
                                   c.threadsNow + ")")
          << (c.interrupted ? "  [stale: interrupted]" : "") << "\n";
    else if (c.status == CaseStatus::Failed)
      out << "  failed   " << c.name << ": " << c.error << "\n";
    else if (c.status == CaseStatus::Pending && c.error.rfind("results.csv says ok", 0) == 0)
      out << "  pending  " << c.name << ": " << c.error << "\n";
    for (const std::string& w : c.warnings) out << "  warning  " << c.name << ": " << w << "\n";
  }
  for (const BedAtAGlance& b : s.beds)
    out << "  bed      " << b.key
        << (b.state == BedAtAGlance::State::Making     ? ": being made"
            : b.state == BedAtAGlance::State::PartMade ? ": part-made, not being made (the same `wiggle sweep` command "
                                                         "continues it)"
                                                       : ": not being made, nothing of it saved")
        << (b.report.empty() ? "" : ": " + b.report) << "\n";
  if (s.replicated()) {
    out << "cells (a case without its seed; V_y as the mean +- standard error over its beds; " << kCellVerdictRule
        << "):\n";
    for (const CellAtAGlance& c : s.cells)
      out << "  cell     " << c.name << ": " << cellInWords(c.stats, c.beds) << "\n";
  }
  if (running + pending == 0 && failed > 0)
    out << "nothing left to run but the " << failed << " failed case" << (failed > 1 ? "s" : "")
        << ": the same `wiggle sweep` command retries " << (failed > 1 ? "them" : "it") << "\n";
  else if (running + pending == 0)
    out << "every case is done\n";
  else if (s.caseTime == SweepStatus::CaseTime::Unknown)
    out << "time to go: unknown until a case has finished or a running one knows its pace"
        << (s.bedsToMake > 0 ? "; the " + bedsToMakeText(s) + " first" : "") << "\n";
  else
    out << "time to go: about " << formatDuration(s.etaSeconds)
        << " (estimate: " << (ownEstimates ? "the running cases' own times to go, plus " : "")
        << (s.caseTime == SweepStatus::CaseTime::FinishedCases
                ? "the finished cases' median wall time"
                : "a case's wall time at the running cases' present pace, nothing having finished yet,")
        << (ownEstimates ? " x the other cases left" : " x the cases left")
        << (s.bedsToMake > 0 ? ", plus the " + bedsToMakeText(s) : "") << ", over " << s.casesAtOnce << " job"
        << (s.casesAtOnce > 1 ? "s" : "") << (ownEstimates ? ", and no less than the longest running case's" : "")
        << (s.bedsCounted ? "" : "; beds still to make are not counted: the sweep's start did not record them")
        << ")\n";
  return out.str();
}

std::optional<RunDirStatus> readRunDirStatus(const std::string& dir) {
  if (!fs::is_directory(dir) || !holdsRun(dir)) return std::nullopt;
  RunDirStatus r;
  r.dir = dir;
  const std::optional<RunProgress> progress = readRunProgress(dir);
  r.hasProgress = progress.has_value();
  r.progress = progress.value_or(RunProgress{RunPhase::Finished, "finished"});
  if (FileLock::holders(runLockPath(dir)) != FileLock::Holders::None) {
    r.state = RunDirState::Running;
  } else if (caseFinished(dir) && r.progress.phase == RunPhase::Finished) {
    // progress.json says finished only once summary.json is written; any other phase beside a
    // summary.json is a later resume (an extension) that stopped.
    r.state = RunDirState::Done;
    const CaseResult summary = readCaseSummary(dir);
    r.vy = summary.summary.vy;
    r.warnings = summary.summary.warnings;
    return r;
  } else {
    r.state = RunDirState::Stopped;
  }
  r.warnings = readRunWarnings(dir);
  return r;
}

std::string formatRunDirStatus(const RunDirStatus& r) {
  const RunProgress& p = r.progress;
  const std::string ofDuration =
      " of " + formatNumber(p.duration) +
      (p.fraction >= 0 ? " (" + formatNumber(100.0 * p.fraction, 3) + " % of its steps)" : "");
  const std::string resume = "; continue with: wiggle run --out " + r.dir + " --resume";
  std::ostringstream out;
  out << "run " << r.dir << ": ";
  if (r.state == RunDirState::Done)
    out << "done" << (r.hasProgress ? " (t = " + formatNumber(p.t) + ")" : "") << ": V_y = " << formatNumber(r.vy)
        << ", summary in " << r.dir << "/summary.json";
  else if (r.state == RunDirState::Running)
    out << "running, " << (p.fraction >= 0 ? "t = " + formatNumber(p.t) + ofDuration : p.stage)
        << (p.etaSeconds >= 0 ? ", about " + formatDuration(p.etaSeconds) + " to go" : "") << threadsNowWords(p);
  else if (p.phase == RunPhase::Failed)
    out << p.stage;
  else if (p.phase == RunPhase::Interrupted)
    out << p.stage << (p.fraction >= 0 ? ofDuration : "") << resume;
  else  // its process ended without a word (SIGKILL, a crash, a power cut): the last stage it wrote
    out << "interrupted (its process ended without saying why: killed?) "
        << (p.fraction >= 0 ? "after t = " + formatNumber(p.t) + ofDuration : "while " + p.stage) << resume
        << " (from its last checkpoint, or from its bed if it wrote none)";
  out << "\n";
  for (const std::string& w : r.warnings) out << "  warning: " << w << "\n";
  return out.str();
}

std::string sweepStatusJson(const SweepStatus& s) {
  using nlohmann::json;
  json cases = json::array();
  for (const CaseAtAGlance& c : s.cases) {
    const bool ok = c.status == CaseStatus::Ok;
    cases.push_back({{"name", c.name},
                     {"status", choiceName(c.status)},
                     {"error", c.error},
                     {"vy", ok ? json(c.vy) : json(nullptr)},
                     {"wall_s", ok ? json(c.wallSeconds) : json(nullptr)},
                     {"fraction", c.fraction >= 0 ? json(c.fraction) : json(nullptr)},
                     {"interrupted", c.interrupted},
                     {"warnings", c.warnings}});
  }
  const json out = {{"dir", s.dir},
                    {"name", s.name},
                    {"sweep_running", s.sweepRunning()},
                    {"jobs", s.jobs},
                    {"eta_s", s.etaSeconds >= 0 ? json(s.etaSeconds) : json(nullptr)},
                    {"text", formatSweepStatus(s)},
                    {"cases", cases}};
  return out.dump(1, ' ', false, json::error_handler_t::replace) + "\n";  // errors may hold any bytes
}

}  // namespace wiggle
