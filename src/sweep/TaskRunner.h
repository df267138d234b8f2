#pragma once
// Runs a sweep's tasks as child processes of the `wiggle` binary (docs/SWEEPS.md explains why
// processes and not threads), through the sweep command's one internal entry (kCaseTaskFlag,
// kBedTaskFlag; the command hands them to runSweepCase and makeSweepBed below):
//   a case:  wiggle sweep --run-case CASE_DIR/config.toml --out CASE_DIR --threads T
//   a bed:   wiggle sweep --make-bed OUT/beds/bed-<key>.toml --threads T
// Each child's stdout and stderr are appended to CASE_DIR/sweep-child.log (OUT/beds/bed-<key>.log);
// a failure is described by the last error line the child printed in that attempt, or the signal
// that killed it. Children get SIGTERM when their parent dies (PR_SET_PDEATHSIG), so a killed sweep
// or MPI rank leaves no orphan writing into a run directory; `wiggle run` answers SIGTERM by
// writing a checkpoint and stopping, which a rerun resumes from.
#include <sys/types.h>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "io/SweepSpec.h"
#include "sweep/ResultsTable.h"

namespace wiggle {

// The flags of `wiggle sweep` that run one task in a child process (hidden from --help).
inline constexpr const char* kCaseTaskFlag = "--run-case";
inline constexpr const char* kBedTaskFlag = "--make-bed";

// A unit of work, as it travels between MPI ranks: make the bed of case `caseIndex`'s config, or
// run case `caseIndex`. Every rank expands the same sweep file, so the index is enough.
struct SweepTask {
  enum class Kind : std::uint8_t { Bed, Case };
  Kind kind = Kind::Case;
  std::size_t caseIndex = 0;

  std::int64_t encode() const;
  static SweepTask decode(std::int64_t code);
  bool operator==(const SweepTask&) const = default;
};

struct TaskOutcome {
  SweepTask task;
  bool ok = false;
  CaseResult result;   // for a case: summary values when ok; status "failed" and error otherwise
  std::string error;   // one line, empty when ok
  double wallSeconds = 0.0;
  int pid = 0;

  std::string toJson() const;
  static TaskOutcome fromJson(const std::string& text);
};

class TaskRunner {
 public:
  // `executable`: the wiggle binary; `threads`: --threads of each child (>= 1).
  TaskRunner(const SweepSpec& spec, std::string outDir, std::string executable, int threads);
  ~TaskRunner();  // sends SIGTERM to children still running and waits for them
  TaskRunner(const TaskRunner&) = delete;
  TaskRunner& operator=(const TaskRunner&) = delete;

  // Prepares the task's directory and config file and starts its child. Returns the child's pid.
  // Throws wiggle::Error when the directory or the process cannot be made.
  pid_t start(const SweepTask& task);

  // Children that have exited since the last call (non-blocking).
  std::vector<TaskOutcome> poll();

  std::size_t running() const { return children_.size(); }
  void signalAll(int signal);

 private:
  struct Child {
    pid_t pid;
    SweepTask task;
    std::string logPath;
    std::uintmax_t logOffset;  // the log's length when this attempt started
    double startSeconds;
  };
  TaskOutcome finish(const Child& child, int waitStatus);

  const SweepSpec& spec_;
  std::string outDir_, executable_;
  int threads_;
  std::vector<Child> children_;
};

// The one line that says why a child failed: in `logTail` (what it printed), the last line
// starting with "wiggle: " that is not a warning, without that prefix; else the last non-empty line.
std::string failureLine(const std::string& logTail);

// Seconds on a monotonic clock (for wall times and the ETA).
double monotonicSeconds();

// The bed task of a sweep (`wiggle sweep --make-bed CONFIG.toml`): obtains (makes and caches) the
// bed of that run config with `threads` OpenMP threads (0 = default), and ends its log
// (beds/bed-KEY.log) with the line bedTaskDoneLine makes.
void makeSweepBed(const std::string& configPath, int threads);
// "bed KEY made and cached (N grains)", or "bed KEY was cached (N grains)"; and whether `line` is
// such a line of the bed `key` (`wiggle status` reads it).
std::string bedTaskDoneLine(const std::string& key, bool fromCache, std::uint32_t grains);
bool isBedTaskDoneLine(const std::string& line, const std::string& key);

// The case task of a sweep (`wiggle sweep --run-case CONFIG.toml --out DIR`): runs that config in
// DIR, continuing from DIR's checkpoint when there is one (a run stopped, killed or extended),
// without a progress line or figures. A failure is a wiggle::Error, printed by the command as the
// child's last error line, which the sweep records.
void runSweepCase(const std::string& configPath, const std::string& runDir, int threads);

}  // namespace wiggle
