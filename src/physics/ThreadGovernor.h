#pragma once
// How many threads a step runs on, changed while a run goes so that it never crawls on a shared
// machine (docs/PERFORMANCE.md, "Threads on a busy machine"). The step's threads meet at barriers
// several times a step; when another process takes one of their cores, the threads whose partner was
// descheduled wait for it a whole time slice, step after step (measured 10-20 x slower than one
// thread). The governor samples the steps' parallel regions (StepProfile's per-thread work), sheds a
// thread while the threads mostly wait, and tries one again: soon when the machine shows an idle core,
// else after a wait that doubles with each failed trial; a trial holds when the threads no longer
// mostly wait. Every result is bitwise the same at any thread count
// (World.h), so this changes the speed only; the governor is never saved and never in a hash.
#include <chrono>
#include <cstdint>
#include <utility>
#include <vector>

#include "physics/StepProfile.h"

namespace wiggle {

enum class ThreadPolicy : std::uint8_t {
  Adaptive,   // shed and retake threads as the machine's load changes (the default)
  Fixed,      // always the ceiling (omp_get_max_threads()): benchmarks of a given thread count
  Scheduled,  // the counts of ThreadGovernor::schedule at given steps: tests of the switching itself
};

// Why the thread count changed: for the run's log.
enum class ThreadChangeReason : std::uint8_t {
  Waiting,    // the threads waited more than ThreadRule::kShedAbove: a thread shed
  IdleCore,   // a core stood idle: a retake
  Trial,      // no idle core seen, the retry time passed: a retake to try
  Ceiling,    // the run's own thread count fell below it
  Scheduled,  // ThreadPolicy::Scheduled
};

// What the governor measured over one stretch of the run at one thread count.
struct ThreadWindow {
  double seconds = 0.0;    // the stretch's wall time
  double waitShare = 0.0;  // the threads' waiting in the sampled parallel regions, 0-1 (waitingShare)
  double idleCores = -1;   // cores of this process's CPUs nothing ran on in the stretch; < 0: unknown
};

// The waiting of a window's sampled regions as a share of what n threads can wait at most: a region
// whose threads all finish together waits 0, one where n - 1 threads wait all through for the last
// one waits 1 (so 0.5 means the threads wait as long as they work, whatever n is).
double waitingShare(const StepProfile::RegionTotals& regions, int threads);

// The rule alone, window by window, without clocks (tested on made-up windows).
class ThreadRule {
 public:
  // waitingShare above which a thread is shed: two threads on a quiet core pair wait 0.15-0.3 of what
  // they can (the paper-depth preset) to 0.45-0.5 (the small bed); beside a CPU-bound process
  // 0.9-1 (docs/PERFORMANCE.md, "Threads on a busy machine").
  static constexpr double kShedAbove = 0.75;
  static constexpr double kIdleToRetake = 0.75;  // idle cores that make a retake worth trying at once
  static constexpr double kFirstRetry = 5.0;     // seconds after a change before a retake is tried
  static constexpr double kLongestRetry = 320.0; // the wait after failed trials doubles up to this

  // The thread count for the next window, after a window measured at `threads` (of at most `ceiling`).
  int next(int threads, int ceiling, const ThreadWindow& window);
  // Why the last change that next() made was made.
  ThreadChangeReason reason() const { return reason_; }

 private:
  double sinceChange_ = 0.0;
  double retryAfter_ = kFirstRetry;
  bool trial_ = false;        // the window just measured was a retake's first: it decides whether it holds
  bool trialOnIdle_ = false;  // that retake was made because cores stood idle
  bool idleMisled_ = false;   // a retake on idle cores failed: wait for the retry time until one holds
  ThreadChangeReason reason_ = ThreadChangeReason::Waiting;
};

// One change of the thread count, for the run's log and summary.
struct ThreadChange {
  double seconds = 0.0;  // since the governor's first step
  std::uint64_t step = 0;
  int from = 0, to = 0;
  ThreadChangeReason reason = ThreadChangeReason::Waiting;
};

class ThreadGovernor {
 public:
  using Clock = std::chrono::steady_clock;
  static constexpr std::uint64_t kSampleEvery = 4;  // steps between sampled steps
  static constexpr double kWindowSeconds = 0.5;     // a window's wall time, at least
  static constexpr std::uint64_t kWindowSamples = 8;  // and its sampled steps, at least

  void setPolicy(ThreadPolicy policy) { policy_ = policy; }
  ThreadPolicy policy() const { return policy_; }
  // ThreadPolicy::Scheduled: from each (step, threads) on, that many threads (capped by the ceiling).
  void setSchedule(std::vector<std::pair<std::uint64_t, int>> schedule) { schedule_ = std::move(schedule); }

  // Before step `step` (the count of steps done): the threads it runs on, at most `ceiling`; marks the
  // step in `profile` to be sampled when the governor measures it.
  int beforeStep(std::uint64_t step, int ceiling, StepProfile& profile);
  // After that step: ends a window when it is long enough, and decides.
  void afterStep(std::uint64_t step, const StepProfile& profile);

  int threads() const { return threads_; }  // of the last step (0 before the first)
  // Wall seconds spent at each thread count so far, index = count (ThreadPolicy::Adaptive; empty
  // before its first step or when the ceiling is one thread).
  std::vector<double> secondsAt() const;
  const std::vector<ThreadChange>& changes() const { return changes_; }

 private:
  void startWindow(Clock::time_point now, const StepProfile& profile);
  void endWindow(std::uint64_t step, Clock::time_point now, const StepProfile& profile);
  void change(std::uint64_t step, int to, ThreadChangeReason reason);

  ThreadPolicy policy_ = ThreadPolicy::Adaptive;
  std::vector<std::pair<std::uint64_t, int>> schedule_;
  ThreadRule rule_;
  int threads_ = 0, ceiling_ = 0;
  bool sampling_ = false;  // the step now running is sampled
  std::uint64_t samples_ = 0;
  Clock::time_point start_{}, windowStart_{}, lastSample_{};
  StepProfile::RegionTotals windowRegions_;  // the profile's sums at the window's start
  double windowIdle_ = -1.0;                 // idleCpuSeconds() at the window's start
  std::vector<double> secondsAt_;
  std::vector<ThreadChange> changes_;
};

}  // namespace wiggle
