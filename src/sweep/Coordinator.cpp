#include "sweep/Coordinator.h"

#include <unistd.h>

#include <chrono>
#include <csignal>
#include <deque>
#include <filesystem>
#include <map>
#include <set>
#include <thread>

#include "core/Console.h"
#include "core/Error.h"
#include "core/Format.h"
#include "core/StopSignal.h"
#include "io/AtomicFile.h"
#include "io/FileLock.h"
#include "scenario/run/RunProgress.h"
#include "sweep/CellTable.h"
#include "sweep/ResultsTable.h"
#include "sweep/SweepStart.h"
#include "sweep/TaskRunner.h"

namespace wiggle {

namespace fs = std::filesystem;

namespace {

std::string hostName() {
  char name[256] = {};
  ::gethostname(name, sizeof name - 1);
  return name;
}

// The sweep's voice: events go to sweep.log and stderr; the status line is rewritten on a terminal
// and logged (and echoed to stderr when there is no terminal) once a minute.
class Monitor {
 public:
  Monitor(const std::string& logPath, const SweepOptions& options)
      : log_(logPath),
        status_(
            options.progress,
            [this](const std::string& text) {
              log_.line(text);
              if (echo_) std::fprintf(stderr, "%s\n", text.c_str());
            },
            60.0),
        echo_(!status_.onTerminal() && options.logToStderr) {}

  void event(const std::string& text) {
    log_.line(text);
    status_.clear();
    if (status_.onTerminal() || echo_) std::fprintf(stderr, "%s\n", text.c_str());
  }

  // A line for sweep.log alone: the caller says it to the user.
  void record(const std::string& text) {
    log_.line(text);
    status_.clear();
  }

  void status(const std::string& text, bool force = false) { status_.update(text, force); }
  void clear() { status_.clear(); }

 private:
  LogFile log_;
  ProgressLine status_;
  bool echo_;
};

enum class BedState { Waiting, Running, Done, Failed };

// Rank 0 (or the only process): hands tasks to local children and to MPI worker ranks.
class Coordinator {
 public:
  // `only`: the one case to run (--case), or nullopt for all of them.
  Coordinator(SweepPlan& plan, const SweepRunSettings& settings, const SweepOptions& options, MpiQueue* mpi,
              std::optional<std::size_t> only)
      : only_(only),
        plan_(plan),
        settings_(settings),
        options_(options),
        mpi_(mpi),
        monitor_(plan.outDir + "/sweep.log", options),
        runner_(plan.spec, plan.outDir, settings.executable, settings.threads) {}

  SweepOutcome run() {
    loadPlan();
    announce();
    writeResults();
    while (true) {
      if (const int signal = stopSignalReceived(); signal != 0 && !stopping_) {
        stopping_ = true;
        stopSignal_ = signal;
        monitor_.event("signal " + std::to_string(signal) + ": stopping; running cases write a checkpoint");
        runner_.signalAll(SIGTERM);
      }
      bool progressed = handOutWork();
      for (const TaskOutcome& o : runner_.poll()) {
        handle(o, "");
        progressed = true;
      }
      progressed = pollWorkerRanks() || progressed;
      if (resultsDirty_) writeResults();
      const bool busy = runner_.running() > 0 || remoteRunning_ > 0;
      if (!busy && (stopping_ || !workLeft())) break;
      if (!progressed) {
        monitor_.status(statusLine());
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
      }
    }
    monitor_.clear();
    releaseWorkerRanks();
    return outcome();
  }

 private:
  // The plan's cases as they stand: finished ones read back, failed ones recorded; with --case the
  // other cases are someone else's, only read, never run.
  void loadPlan() {
    const std::size_t n = plan_.cases.size();
    results_.assign(n, CaseResult{});
    started_.assign(n, false);
    bedState_.assign(plan_.beds.size(), BedState::Waiting);
    ownBeds_ = bedsMadeBy(plan_, only_);
    for (std::size_t c = 0; c < n; ++c) {
      const PlannedCase& p = plan_.cases[c];
      runDirs_.push_back(p.runDir);
      if (p.state == CaseState::Done) {
        try {
          results_[c] = readCaseSummary(p.dir);
          started_[c] = true;
        } catch (const Error&) {
          results_[c] = CaseResult{};  // unreadable after all: run it again
        }
      } else if (p.state == CaseState::Failed) {
        results_[c].status = CaseStatus::Failed;
        results_[c].error = p.error;
        started_[c] = true;
      }
      if (!counts(c)) started_[c] = true;
    }
    const int workers = mpi_ ? mpi_->size() - 1 : 0;
    concurrency_ = mpi_ ? std::max(1, workers * settings_.jobs) : std::max(1, settings_.jobs);
  }

  void announce() {
    const std::string pid = std::to_string(::getpid());
    std::vector<BedToMake> beds;
    for (const PlannedBed& b : plan_.beds) beds.push_back({b.key, b.cachePath, b.estimatedSeconds});
    writeSweepStart(plan_.outDir,
                    {plan_.spec.settings.name, only_ ? 0 : concurrency_, settings_.threads, std::move(beds)});
    if (only_) {
      monitor_.event("wiggle sweep " + plan_.spec.settings.name + " --case " + std::to_string(*only_ + 1) + ": " +
                     plan_.spec.cases[*only_].name + " (pid " + pid + ")");
    } else {
      const std::string layout =
          mpi_ ? std::to_string(mpi_->size() - 1) + " MPI worker ranks x " + std::to_string(settings_.jobs) + " jobs"
               : std::to_string(settings_.jobs) + " jobs";
      monitor_.event("wiggle sweep " + plan_.spec.settings.name + ": " + std::to_string(plan_.cases.size()) +
                     " cases, " + std::to_string(countStatus(CaseStatus::Ok)) + " done before, " +
                     std::to_string(plan_.beds.size()) + " beds to make; " + layout + " x " +
                     std::to_string(settings_.threads) + " threads; host " + hostName() + " pid " + pid);
    }
    for (std::size_t c = 0; c < plan_.cases.size(); ++c)
      if (counts(c) && results_[c].status == CaseStatus::Failed)
        monitor_.event("failed " + plan_.spec.cases[c].name + ": " + results_[c].error);
  }

  // Starts tasks while there are free local slots or waiting worker ranks; whether any started.
  bool handOutWork() {
    const std::size_t localSlots = mpi_ ? 0 : static_cast<std::size_t>(settings_.jobs);
    bool started = false;
    while (true) {
      const bool local = runner_.running() < localSlots;
      if (!local && waitingRanks_.empty()) break;
      const std::optional<SweepTask> task = nextTask();
      if (!task) break;
      markStarted(*task);
      if (local) {
        try {
          const pid_t pid = runner_.start(*task);
          monitor_.event("start " + describe(*task) + " (pid " + std::to_string(pid) + ")");
          if (options_.onTaskStarted) options_.onTaskStarted(*task, pid);
        } catch (const Error& e) {
          TaskOutcome o;
          o.task = *task;
          o.error = e.what();
          o.result.status = CaseStatus::Failed;
          o.result.error = e.what();
          handle(o, "");
        }
      } else {
        const int rank = waitingRanks_.front();
        waitingRanks_.pop_front();
        mpi_->send(rank, MpiTag::Task, std::to_string(task->encode()));
        ++remoteRunning_;
        monitor_.event("start " + describe(*task) + " on rank " + std::to_string(rank) + " (" + rankInfo_[rank] + ")");
      }
      started = true;
      resultsDirty_ = true;
    }
    return started;
  }

  // Requests and results from the worker ranks; whether any came.
  bool pollWorkerRanks() {
    bool any = false;
    while (mpi_) {
      const std::optional<MpiMessage> m = mpi_->poll();
      if (!m) break;
      any = true;
      if (m->tag == MpiTag::Request) {
        if (!rankInfo_.count(m->source)) monitor_.event("rank " + std::to_string(m->source) + " ready: pid " + m->text);
        rankInfo_[m->source] = m->text;
        waitingRanks_.push_back(m->source);
      } else if (m->tag == MpiTag::Result) {
        --remoteRunning_;
        handle(TaskOutcome::fromJson(m->text), " on rank " + std::to_string(m->source));
      }
    }
    return any;
  }

  // Releases the workers: each has (or will have) one request outstanding.
  void releaseWorkerRanks() {
    if (!mpi_) return;
    const int workers = mpi_->size() - 1;
    int stopped = 0;
    std::set<int> released;
    while (stopped < workers) {
      while (!waitingRanks_.empty()) {
        const int rank = waitingRanks_.front();
        waitingRanks_.pop_front();
        if (released.insert(rank).second) {
          mpi_->send(rank, MpiTag::Stop, "");
          ++stopped;
        }
      }
      if (stopped >= workers) break;
      if (const std::optional<MpiMessage> m = mpi_->poll()) {
        if (m->tag == MpiTag::Request) waitingRanks_.push_back(m->source);
      } else {
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
      }
    }
  }

  SweepOutcome outcome() {
    SweepOutcome out;
    out.outDir = plan_.outDir;
    out.cases = only_ ? 1 : plan_.cases.size();
    out.ok = countStatus(CaseStatus::Ok);
    out.failed = countStatus(CaseStatus::Failed);
    out.pending = out.cases - out.ok - out.failed;
    out.interrupted = stopping_;
    out.stopSignal = stopSignal_;
    writeResults();
    const std::string failed = " failed (error column of results.csv)";
    const std::string unfinished = " not finished (rerun the same command to resume)";
    if (only_) {
      out.summary = "sweep " + plan_.outDir + ": case " + plan_.spec.cases[*only_].name +
                    (out.ok ? " ok" : out.failed ? failed : unfinished);
    } else {
      out.summary = "sweep " + plan_.outDir + ": " + std::to_string(out.ok) + " of " + std::to_string(out.cases) +
                    " cases ok";
      if (out.failed) out.summary += ", " + std::to_string(out.failed) + failed;
      if (out.pending) out.summary += ", " + std::to_string(out.pending) + unfinished;
    }
    std::size_t warned = 0;
    for (std::size_t c = 0; c < results_.size(); ++c) warned += counts(c) && !results_[c].summary.warnings.empty();
    if (warned)
      out.summary += "; " + std::to_string(warned) + (warned > 1 ? " cases have" : " case has") +
                     " warnings (warnings column of results.csv, wiggle status)";
    if (options_.summaryAsEvent)
      monitor_.event(out.summary);
    else
      monitor_.record(out.summary);
    return out;
  }

  // Whether case c is this run's to count: every case, or with --case the one.
  bool counts(std::size_t c) const { return !only_ || c == *only_; }

  std::size_t countStatus(CaseStatus s) const {
    std::size_t k = 0;
    for (std::size_t c = 0; c < results_.size(); ++c) k += counts(c) && results_[c].status == s;
    return k;
  }

  std::string describe(const SweepTask& t) const {
    const std::string& name = plan_.spec.cases[t.caseIndex].name;
    if (t.kind == SweepTask::Kind::Case) return "case " + name;
    return "bed " + plan_.cases[t.caseIndex].bedKey + " (for " + name + ")";
  }

  int bedOfTask(const SweepTask& t) const {
    for (std::size_t b = 0; b < plan_.beds.size(); ++b)
      if (plan_.beds[b].firstCase == t.caseIndex) return static_cast<int>(b);
    return -1;
  }

  std::optional<SweepTask> nextTask() {
    if (stopping_) return std::nullopt;
    // In case order: the first case not started runs if its bed is ready, or has its bed made if
    // nobody is making it yet. So results arrive in the sweep's order and beds just in time: a long
    // sweep stopped early has its first cases done rather than all its beds, and with many workers
    // every bed still starts at once (no case can run before its bed).
    for (std::size_t c = 0; c < plan_.cases.size(); ++c) {
      if (started_[c]) continue;
      const int b = plan_.cases[c].bedTask;
      if (b < 0 || bedState_[b] == BedState::Done) return SweepTask{SweepTask::Kind::Case, c};
      if (bedState_[b] == BedState::Waiting) return SweepTask{SweepTask::Kind::Bed, plan_.beds[b].firstCase};
    }
    return std::nullopt;
  }

  // A waiting bed is not work by itself: it is made when a case that needs it comes up, so it is
  // covered by that case not having started. With --case the other cases' beds are never made, and
  // counting them kept a finished array task waiting for ever.
  bool workLeft() const {
    for (const BedState s : bedState_)
      if (s == BedState::Running) return true;
    for (std::size_t c = 0; c < started_.size(); ++c)
      if (!started_[c]) return true;
    return false;
  }

  void markStarted(const SweepTask& t) {
    running_[t.encode()] = monotonicSeconds();
    if (t.kind == SweepTask::Kind::Bed) {
      bedState_[bedOfTask(t)] = BedState::Running;
    } else {
      started_[t.caseIndex] = true;
      results_[t.caseIndex] = CaseResult{};
      results_[t.caseIndex].status = CaseStatus::Running;
    }
  }

  void handle(const TaskOutcome& o, const std::string& where) {
    running_.erase(o.task.encode());
    resultsDirty_ = true;
    if (o.task.kind == SweepTask::Kind::Bed) {
      const int b = bedOfTask(o.task);
      if (o.ok) {
        bedState_[b] = BedState::Done;
        ++bedsMade_;
        monitor_.event("bed " + plan_.beds[b].key + " ready" + where + " (" + formatDuration(o.wallSeconds) + ")");
        return;
      }
      if (stopping_) {  // stopped by us, its partial bed saved: its cases stay pending
        bedState_[b] = BedState::Waiting;
        monitor_.event("bed " + plan_.beds[b].key + " stopped" + where + ": " + o.error);
        return;
      }
      bedState_[b] = BedState::Failed;
      monitor_.event("bed " + plan_.beds[b].key + " failed" + where + ": " + o.error);
      for (std::size_t c = 0; c < plan_.cases.size(); ++c) {
        if (plan_.cases[c].bedTask != b || started_[c]) continue;
        started_[c] = true;
        results_[c].status = CaseStatus::Failed;
        results_[c].error = "making its bed failed: " + o.error;
      }
      return;
    }
    const std::size_t c = o.task.caseIndex;
    const std::string& name = plan_.spec.cases[c].name;
    if (o.ok) {
      results_[c] = o.result;
      results_[c].status = CaseStatus::Ok;
      monitor_.event("ok " + name + where + ": vy = " + formatNumber(o.result.summary.vy, 4) + ", " + formatDuration(o.wallSeconds) + ", " +
                     formatNumber(o.result.summary.nsPerParticleStep, 3) + " ns/particle-step");
      for (const std::string& w : o.result.summary.warnings) monitor_.event("warning " + name + ": " + w);
      return;
    }
    results_[c] = CaseResult{};
    if (stopping_) {
      results_[c].status = CaseStatus::Pending;
      results_[c].error = interruptedError(o.error);
      monitor_.event("stopped " + name + where + ": " + o.error);
    } else {
      results_[c].status = CaseStatus::Failed;
      results_[c].error = o.error;
      monitor_.event("failed " + name + where + ": " + o.error);
    }
  }

  // results.csv and, from the same results, cells.csv (sweep/CellTable.h), one after the other.
  void writeTables(const std::vector<CaseResult>& table) {
    writeFileAtomically(plan_.outDir + "/results.csv", resultsCsv(plan_.spec, runDirs_, table));
    writeFileAtomically(plan_.outDir + "/cells.csv", cellsCsv(plan_.spec, table));
    resultsDirty_ = false;
  }

  void writeResults() {
    if (!only_) {
      writeTables(results_);
      return;
    }
    // One case of several processes': the table is rebuilt under a lock, so that the last process to
    // write has seen every other case as its own process left it: finished, from its summary.json
    // (written before that process takes the lock); failed or interrupted, from the row that process
    // wrote, which this process's view from its start predates.
    FileLock lock(plan_.outDir + "/.results.lock", false, true, "results.csv is being rewritten");
    std::vector<CaseResult> table = results_;
    const std::map<std::string, CaseResult> written = readUnfinishedRows(plan_.outDir);
    for (std::size_t c = 0; c < table.size(); ++c) {
      if (c == *only_) continue;
      if (fs::exists(plan_.cases[c].dir + "/summary.json")) {
        try {
          table[c] = readCaseSummary(plan_.cases[c].dir);
        } catch (const Error&) {
          // Being written by its own process, or torn: it shows as before.
        }
      } else if (const auto row = written.find(plan_.spec.cases[c].name);
                 row != written.end() && table[c].status == CaseStatus::Pending && table[c].error.empty()) {
        table[c] = row->second;  // this process knows nothing of it since it read the plan
      }
    }
    writeTables(table);
  }

  // Measured over the finished cases this task counts (this session and earlier ones), or the cost model's.
  double nsPerParticleStep() const { return sweepNsPerParticleStep(results_, only_, plan_.speed.ns); }

  // A running case's wall seconds left by its own estimate (progress.json, from the pace of its own
  // steps), once it has one.
  std::optional<double> runningCaseOwnSecondsLeft(std::size_t c) const {
    const std::optional<RunProgress> progress = readRunProgress(plan_.cases[c].dir);
    if (progress && progress->etaSeconds >= 0.0) return progress->etaSeconds;
    return std::nullopt;
  }

  // The cost estimate less the time it has run, for a running case without an estimate of its own
  // (just started, or a wiggle that writes none): it reaches 0 and stays there when the case is
  // slower than the estimate (a resumed case, a busy machine).
  double runningCaseModelSecondsLeft(std::size_t c, double ns) const {
    const auto it = running_.find(SweepTask{SweepTask::Kind::Case, c}.encode());
    const double elapsed = it == running_.end() ? 0.0 : monotonicSeconds() - it->second;
    return std::max(0.0, estimatedRunSeconds(plan_.spec.cases[c].config, ns) - elapsed);
  }

  // The ETA says what it rests on: the ns per particle-step of the cost model (or of this sweep's
  // finished cases) when any part of it does, else the running cases' own pace, so that a machine
  // slower than the cost table's does not read as running at the table's speed.
  std::string statusLine() const {
    const double ns = nsPerParticleStep();
    double remaining = 0.0;  // wall seconds of work left, summed over tasks
    bool byModel = false;    // some of it from ns rather than a running case's own pace
    std::size_t left = 0, running = 0;
    for (std::size_t c = 0; c < plan_.cases.size(); ++c) {
      const RunConfig& config = plan_.spec.cases[c].config;
      if (!started_[c]) {
        ++left;
        remaining += estimatedRunSeconds(config, ns);
        byModel = true;
      } else if (results_[c].status == CaseStatus::Running) {
        ++running;
        if (const std::optional<double> own = runningCaseOwnSecondsLeft(c)) {
          remaining += *own;
        } else {
          remaining += runningCaseModelSecondsLeft(c, ns);
          byModel = true;
        }
      }
    }
    for (const std::size_t b : ownBeds_) {
      if (bedState_[b] == BedState::Waiting || bedState_[b] == BedState::Running) {
        remaining += plan_.beds[b].estimatedSeconds * ns / plan_.speed.ns;  // planned at that speed
        byModel = true;
      }
    }
    std::string line = "[sweep] " + std::to_string(countStatus(CaseStatus::Ok)) + " done, " + std::to_string(running) +
                       " running, " + std::to_string(countStatus(CaseStatus::Failed)) + " failed, " + std::to_string(left) + " left";
    if (!ownBeds_.empty()) line += ", beds " + std::to_string(bedsMade_) + "/" + std::to_string(ownBeds_.size());
    line += "  ETA " + formatDuration(remaining / concurrency_) +
            (byModel ? " (" + formatNumber(ns, 3) + " ns/particle-step" +
                           (countStatus(CaseStatus::Ok) == 0 ? ", estimated)" : ")")
                     : " (the running cases' own pace)");
    return line;
  }

  std::optional<std::size_t> only_;
  SweepPlan& plan_;
  const SweepRunSettings& settings_;
  const SweepOptions& options_;
  MpiQueue* mpi_;
  Monitor monitor_;
  TaskRunner runner_;
  std::vector<CaseResult> results_;
  std::vector<std::string> runDirs_;
  std::vector<bool> started_;  // dispatched, finished before, or failed without running
  std::vector<BedState> bedState_;
  std::vector<std::size_t> ownBeds_;  // the beds this run makes (bedsMadeBy): its status line counts only these
  std::map<std::int64_t, double> running_;  // task code -> start time
  std::deque<int> waitingRanks_;
  std::map<int, std::string> rankInfo_;
  int remoteRunning_ = 0;
  int concurrency_ = 1;
  std::size_t bedsMade_ = 0;
  bool stopping_ = false;
  int stopSignal_ = 0;  // the signal that set stopping_
  bool resultsDirty_ = false;
};

SweepOutcome workerLoop(const SweepPlan& plan, const SweepRunSettings& settings, MpiQueue& mpi) {
  TaskRunner runner(plan.spec, plan.outDir, settings.executable, settings.threads);
  const std::string hello = std::to_string(::getpid()) + " on " + hostName();
  bool outstanding = false, stopping = false;
  while (true) {
    bool progressed = false;
    if (!stopping && !outstanding && runner.running() < static_cast<std::size_t>(settings.jobs)) {
      mpi.send(0, MpiTag::Request, hello);
      outstanding = true;
    }
    // Nothing is read after the Stop: what rank 0 sends next (a boundary study's next round) is
    // for whoever serves after this loop.
    while (!stopping) {
      const std::optional<MpiMessage> m = mpi.poll();
      if (!m) break;
      progressed = true;
      if (m->tag == MpiTag::Stop) {
        stopping = true;
        outstanding = false;
      } else if (m->tag == MpiTag::Task) {
        outstanding = false;
        const SweepTask task = SweepTask::decode(std::stoll(m->text));
        try {
          runner.start(task);
        } catch (const Error& e) {
          TaskOutcome o;
          o.task = task;
          o.error = e.what();
          o.result.status = CaseStatus::Failed;
          o.result.error = e.what();
          mpi.send(0, MpiTag::Result, o.toJson());
        }
      }
    }
    for (const TaskOutcome& o : runner.poll()) {
      mpi.send(0, MpiTag::Result, o.toJson());
      progressed = true;
    }
    if (stopping && runner.running() == 0) break;
    if (!progressed) std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  SweepOutcome out;
  out.worker = true;
  out.outDir = plan.outDir;
  return out;
}

}  // namespace

SweepOutcome coordinateSweep(SweepPlan& plan, const SweepRunSettings& settings, const SweepOptions& options,
                             MpiQueue* mpi, std::optional<std::size_t> only) {
  Coordinator coordinator(plan, settings, options, mpi, only);
  return coordinator.run();
}

SweepOutcome runWorkerRank(const SweepPlan& plan, const SweepRunSettings& settings, MpiQueue& mpi) {
  return workerLoop(plan, settings, mpi);
}

}  // namespace wiggle
