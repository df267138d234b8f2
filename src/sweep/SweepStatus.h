#pragma once
// `wiggle status DIR`: a sweep directory at a glance, from what the sweep leaves on disk (results.csv,
// each case's progress.json, the directory's lock and each run's), without touching it: per case
// done, running (with how far it got), failed (with its error) or pending, and an estimated time to go.
#include <optional>
#include <string>
#include <vector>

#include "io/FileLock.h"
#include "scenario/run/RunProgress.h"
#include "sweep/CellTable.h"
#include "sweep/ResultsTable.h"  // CaseStatus

namespace wiggle {

// One case's line of the glance.
struct CaseAtAGlance {
  std::string name;
  // As results.csv says, except that a case is ok only when its summary.json says so
  // (caseFinished, sweep/ResultsTable.h): else it is pending, as the sweep would rerun it, and
  // `error` says why.
  CaseStatus status = CaseStatus::Pending;
  std::string error;    // failed: the recorded error
  double vy = 0.0;      // ok: the rise rate
  double wallSeconds = 0.0;  // ok: the case's wall time
  double fraction = -1.0;    // running: the fraction of its steps done (its progress.json), else -1
  double etaSeconds = -1.0;  // running: its run's own estimate of the wall seconds left (progress.json), else -1
  std::string threadsNow;    // running: ", on 2 threads" (threadsNowWords), else 
  std::string stage;         // running, before its first step: what its progress.json says it is doing
  std::vector<std::string> warnings;  // ok: summary.json's; running: its warnings.txt so far
  // running: no process runs it now (neither its run's lock nor a whole sweep's is held): the
  // sweep that ran it was stopped or killed, and the same command continues it.
  bool interrupted = false;
};

// A bed the sweep began to make (its beds/bed-KEY.toml) and the cache does not hold yet: a deep or
// wide bed takes hours, in which no case runs.
struct BedAtAGlance {
  enum class State {
    Making,    // a process holds the bed's lock in the cache: it is being made now
    PartMade,  // nobody makes it, and its partial file is in the cache: the same sweep command continues it
    NotMade,   // nobody makes it and nothing of it is saved (a bed that failed: its log says why)
  };
  std::string key;
  State state = State::NotMade;
  std::string report;  // the bed maker's last report in beds/bed-KEY.log ("[bed] pouring batch 3, ..."), if any
};

// A cell of the sweep (a case without its seed) as its cells.csv says (sweep/CellTable.h).
struct CellAtAGlance {
  std::string name;
  std::size_t beds = 0;  // the beds the sweep gives it
  CellStats stats;       // over those of its beds that have a V_y
};

struct SweepStatus {
  std::string dir;
  std::string name;  // the sweep's name, from sweep.json (empty when unknown)
  std::vector<CaseAtAGlance> cases;
  std::vector<BedAtAGlance> beds;  // in the order of their keys
  // From DIR/cells.csv; empty when there is none (a sweep written by an older wiggle).
  std::vector<CellAtAGlance> cells;
  bool replicated() const;  // some cell has more than one bed: the cells are worth showing
  // Who holds the directory's lock now: a whole sweep (exclusive), one-case tasks (`--case`, shared)
  // or nobody.
  FileLock::Holders sweepLock = FileLock::Holders::None;
  bool sweepRunning() const { return sweepLock != FileLock::Holders::None; }
  int jobs = 0;         // cases at once, from sweep.json (0 = unknown)
  int casesAtOnce = 1;  // what the time to go divides by: the jobs, or the cases running now when more
  // What a case's wall time is taken to be for the time to go.
  enum class CaseTime {
    Unknown,        // nothing has finished, and no running case knows its pace yet
    FinishedCases,  // the finished cases' median wall time (a case paused for hours moves it by one place only)
    RunningPace,    // before any has finished: the median over the running cases of the wall time each
                    // would take whole at its present pace (its estimate of the time left over the
                    // fraction left); a long case's first hours are otherwise blind
  };
  CaseTime caseTime = CaseTime::Unknown;
  // The beds the sweep had to make at its last start (its sweep.json) that the cache does not hold
  // yet, and the sweep plan's estimate of their wall time (its seconds of one core over the sweep's
  // threads); a bed begun counts whole (how far a pour has got is not known from its log).
  // bedsCounted is false when sweep.json does not say (a sweep started by an older wiggle).
  bool bedsCounted = false;
  int bedsToMake = 0;
  double bedSeconds = 0.0;
  // Seconds to go: the running cases' own estimates of their time left, plus caseTime's wall time of a
  // case times the other cases left (an interrupted one counts for what it has left), plus
  // bedSeconds, over casesAtOnce, and never less than the longest running case's time left;
  // negative when caseTime is Unknown.
  double etaSeconds = -1.0;
};

// Throws wiggle::Error when `dir` is not a sweep directory (no results.csv) or results.csv is unreadable.
SweepStatus readSweepStatus(const std::string& dir);

std::string formatSweepStatus(const SweepStatus& status);

// The status as JSON, for `wiggle report` to hand to the plotting package: {"dir", "name",
// "sweep_running", "jobs", "eta_s" (null when unknown), "text" (what `wiggle status` prints),
// "cases": [{"name", "status", "error", "vy", "wall_s", "fraction", "interrupted", "warnings"}]} (vy and wall_s null unless ok,
// fraction null unless a running case's progress.json says how far it got).
std::string sweepStatusJson(const SweepStatus& status);

// `wiggle status RUN_DIR` for one run directory (`wiggle run --out DIR`), from its files alone:
// done (its summary.json says ok and no later run of it is under way), running (a process holds its
// lock), or stopped: interrupted at t (SIGINT/SIGTERM, or killed: no process holds it), failed at t.
enum class RunDirState { Done, Running, Stopped };

struct RunDirStatus {
  std::string dir;
  RunDirState state = RunDirState::Stopped;
  RunProgress progress;  // its progress.json (stage "finished" when a finished run has none)
  bool hasProgress = false;
  double vy = 0.0;                    // done: summary.json's V_y
  std::vector<std::string> warnings;  // done: summary.json's; else warnings.txt so far
};

// Nothing when `dir` holds no run (scenario/Experiment.h holdsRun).
std::optional<RunDirStatus> readRunDirStatus(const std::string& dir);

std::string formatRunDirStatus(const RunDirStatus& status);

}  // namespace wiggle
