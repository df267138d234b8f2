#pragma once
// A run directory's progress.json: what the run is doing and how far it is, written by the run
// (scenario/run/Experiment.cpp) as it goes and read by `wiggle status` and `wiggle report`
// (sweep/SweepStatus), so that they read data, not the log lines written for people. Written
// atomically (io/AtomicFile): a reader sees the previous state or the new one, never half of one.
// docs/OUTPUT-FORMATS.md lists its fields.
#include <optional>
#include <string>

namespace wiggle {

struct RunProgress {
  std::string stage;         // what it is doing, in words: "making or loading its bed", "running", ...
  double fraction = -1.0;    // of the run's steps done; -1 before the run's first step
  double t = 0.0;            // the run's time [sqrt(d/g)]
  double duration = 0.0;     // run.duration [sqrt(d/g)]
  double etaSeconds = -1.0;  // wall seconds left, estimated; -1 when not known yet
};

// The stage of a run stopped by SIGINT or SIGTERM, which checkpointed first ("interrupted at t =
// 12.5"), and of one stopped while its bed was made (the bed cache kept the bed so far). A run
// killed outright (SIGKILL, a crash) cannot say so: its file keeps the last stage it wrote, and
// `wiggle status` finds it interrupted because no process holds its directory's lock.
std::string interruptedStage(double t);
inline constexpr const char* kInterruptedMakingBedStage = "interrupted while making its bed";
// The stage of a run stopped by an error (a blow-up, a full disk): "failed at t = 12.5: why" (one
// stopped by an error while its bed was made or loaded: "failed while making or loading its bed: why").
std::string failedStage(double t, const std::string& why);

std::string runProgressPath(const std::string& runDir);
void writeRunProgress(const std::string& runDir, const RunProgress& progress);
// The run's progress, or nothing when it has none (not started, or run by a wiggle that did not
// write it) or it cannot be read.
std::optional<RunProgress> readRunProgress(const std::string& runDir);

}  // namespace wiggle
