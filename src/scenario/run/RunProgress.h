#pragma once
// A run directory's progress.json: what the run is doing and how far it is, written by the run
// (scenario/run/Experiment.cpp) as it goes and read by `wiggle status` and `wiggle report`
// (sweep/SweepStatus), so that they read data, not the log lines written for people. Written
// atomically (io/AtomicFile): a reader sees the previous state or the new one, never half of one.
// docs/OUTPUT-FORMATS.md lists its fields.
#include <cstdint>
#include <optional>
#include <string>

namespace wiggle {

// Where a run is, as a reader acts on it; `RunProgress::stage` says the same in words for people.
// A run killed outright (SIGKILL, a crash) cannot say that it stopped: its file keeps the last
// phase it wrote, and `wiggle status` finds it stopped because no process holds its directory's lock.
enum class RunPhase {
  Starting,     // its bed made or loaded, or its checkpoint read: no step yet
  Running,      // stepping
  Finished,     // summary.json written
  Interrupted,  // stopped by SIGINT or SIGTERM, after its checkpoint (or while its bed was made: the bed cache kept it)
  Failed,       // stopped by an error (a blow-up, a full disk)
};
const char* runPhaseName(RunPhase phase);  // "starting", "running", ... (progress.json's "phase")

struct RunProgress {
  RunPhase phase = RunPhase::Starting;
  std::string stage;         // the phase in words: "making or loading its bed", "interrupted at t = 12.5", ...
  double fraction = -1.0;    // of the run's steps done; -1 before the run's first step
  double t = 0.0;            // the run's time [sqrt(d/g)]
  double duration = 0.0;     // run.duration [sqrt(d/g)]
  double etaSeconds = -1.0;  // wall seconds left, estimated; -1 when not known yet
  int threads = 0;           // running: the threads its steps use now (physics/ThreadGovernor.h); 0 = not said
};

// The pace of this process's stepping, for the ETA and the progress line: its wall seconds and steps
// since it began. A resumed run's earlier stretches do not count: they may have run on another
// machine, at another thread count or beside other work, and would set the ETA by their pace.
struct StepPace {
  double seconds = 0.0;
  std::uint64_t steps = 0;
  double etaSeconds(std::uint64_t stepsLeft) const;  // -1 before the first step
  double nsPerParticleStep(double particles) const;  // 0 before the first step
};

// The words of a stopped run's stage: "interrupted at t = 12.5" (SIGINT or SIGTERM, its checkpoint
// written), "interrupted while making its bed"; "failed at t = 12.5: why", "failed while making or
// loading its bed: why".
std::string interruptedStage(double t);
inline constexpr const char* kInterruptedMakingBedStage = "interrupted while making its bed";
std::string failedStage(double t, const std::string& why);
std::string failedMakingBedStage(const std::string& why);

// ", on 2 threads" for a running run that says how many threads its steps use now, else "".
std::string threadsNowWords(const RunProgress& progress);

std::string runProgressPath(const std::string& runDir);
void writeRunProgress(const std::string& runDir, const RunProgress& progress);
// The run's progress, or nothing when it has none (not started, or run by a wiggle that did not
// write it) or it cannot be read.
std::optional<RunProgress> readRunProgress(const std::string& runDir);

}  // namespace wiggle
