#pragma once
// Where a step's wall time goes (World::enableStepProfile; `run.profile`, summary.json's
// `step_profile`): the seconds of each named stage of World::advance, and inside the step's
// parallel regions each thread's time working and waiting at the region's end (load imbalance).
// Opt-in and cheap: when off (and the step not sampled), each stage boundary costs one predictable branch; when on, one
// steady_clock read per stage per step on the first thread and two per thread per parallel region,
// into per-thread slots of a cache line each. It reads clocks only: the bits do not change.
#include <array>
#include <chrono>
#include <cstdint>
#include <string_view>
#include <vector>

namespace wiggle {

// The step's stages, in the order World::advance runs them (ARCHITECTURE.md, "The step").
enum class StepStage : std::uint8_t {
  StartGrains,     // the grains' first half kick and drift, when the previous pass did not (parallel)
  IntruderMotion,  // the free intruder's half kick and drift, its prescribed x, its list's check (serial)
  ListSort,        // x wrapped into the box, the grains re-sorted every sort_interval steps (serial)
  ListBuild,       // NeighbourList::build: the half list, history carried (parallel loops and serial parts)
  ListRefresh,     // positions at the build and the Kinematics records (serial)
  IntruderPairs,   // the intruder's pair list (serial)
  ContactForces,   // force blocks, and the intruder's pair kernel on the first thread (parallel)
  IntruderSums,    // the intruder's pair forces onto its grains and the clump, in list order (serial)
  CompleteForces,  // cross pairs, gravity, the kicks, the next step's drift (parallel)
  HealthScan,      // the blow-up detector's full scan (parallel loops, the intruder's pairs serial)
  Count
};

// How a stage runs: on one thread, as one parallel region whose threads' wait the profile measures,
// or both (a list build: its parallel loops and its serial parts are not told apart).
enum class StageKind : std::uint8_t { Serial, Parallel, Mixed };

struct StageInfo {
  std::string_view name;  // summary.json's key
  StageKind kind;
};
const StageInfo& stageInfo(StepStage stage);
std::string_view stageKindName(StageKind kind);

class StepProfile {
 public:
  using Clock = std::chrono::steady_clock;
  static constexpr std::size_t kStages = static_cast<std::size_t>(StepStage::Count);

  struct StageTotals {
    double seconds = 0.0;        // wall time of the stage
    double workSeconds = 0.0;    // parallel stages: the threads' working time, summed over threads
    double waitSeconds = 0.0;    // parallel stages: the threads' time inside the stage not working, summed
    double threadSeconds = 0.0;  // parallel stages: threads x wall time
    std::uint64_t calls = 0;
  };

  // The parallel regions' time, summed over regions and threads: what the thread governor
  // (physics/ThreadGovernor.h) reads of the steps it samples, whether or not the profile is on.
  struct RegionTotals {
    double workSeconds = 0.0, waitSeconds = 0.0, threadSeconds = 0.0;
  };

  bool on() const { return on_; }
  void enable();  // from zero
  void disable() { on_ = false; }
  // Measure the next step's parallel regions into regionTotals() even when the profile is off; its
  // stages and steps count only when it is on, so a sampled step never shows in the report.
  void sampleNextStep() { sampleNext_ = true; }
  const RegionTotals& regionTotals() const { return regions_; }
  const StageTotals& stage(StepStage s) const { return stages_[static_cast<std::size_t>(s)]; }
  double stepSeconds() const { return stepSeconds_; }  // wall time inside World::advance
  std::uint64_t steps() const { return steps_; }
  int threads() const { return threads_; }  // of the last parallel region
  double stagedSeconds() const;             // the stages' seconds summed (= stepSeconds but for the clock reads)
  // Fractions of stepSeconds: in serial stages (the other threads idle); and the parallel stages'
  // waiting, as a fraction of all threads' time in the steps (each step's threads x its seconds:
  // the thread governor may change the count between steps).
  double serialShare() const;
  double waitShare() const;

  // --- for World: a step's stages are laps of one clock ---
  void beginStep() {
    if (on_ || sampleNext_) beginStepNow();
  }
  void endStep() {
    if (inStep_) endStepNow();
  }
  // The time since the last lap (or the step's start) was `stage`'s.
  void lap(StepStage stage) {
    if (inStep_) lapNow(stage);
  }
  bool inStep() const { return inStep_; }
  // Before a parallel region whose threads report their work: one slot per thread.
  void beginRegion(int maxThreads);
  // Inside the region, at the end of thread t's work (of `threads`) begun at `start`.
  void threadWorked(int t, int threads, Clock::time_point start) {
    ThreadSlot& slot = slots_[static_cast<std::size_t>(t)];
    slot.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    if (t == 0) regionThreads_ = threads;
  }

 private:
  void beginStepNow();
  void endStepNow();
  void lapNow(StepStage stage);

  struct alignas(64) ThreadSlot {  // one cache line per thread: no false sharing
    double seconds = 0.0;
  };
  bool on_ = false, sampleNext_ = false, inStep_ = false, regionPending_ = false;
  int threads_ = 1, regionThreads_ = 0;
  Clock::time_point stepStart_{}, last_{};
  std::array<StageTotals, kStages> stages_{};
  RegionTotals regions_;
  double stepSeconds_ = 0.0;
  double threadStepSeconds_ = 0.0;  // each step's seconds x its regions' threads
  int stepThreads_ = 1;
  std::uint64_t steps_ = 0;
  std::vector<ThreadSlot> slots_;
};

}  // namespace wiggle
