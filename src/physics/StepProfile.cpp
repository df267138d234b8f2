#include "physics/StepProfile.h"

#include <algorithm>

namespace wiggle {

namespace {
constexpr std::array<StageInfo, StepProfile::kStages> kStageInfo = {{
    {"start_grains", StageKind::Parallel},
    {"intruder_motion", StageKind::Serial},
    {"list_sort", StageKind::Serial},
    {"list_build", StageKind::Mixed},
    {"list_refresh", StageKind::Serial},
    {"intruder_pairs", StageKind::Serial},
    {"contact_forces", StageKind::Parallel},
    {"intruder_sums", StageKind::Serial},
    {"complete_forces", StageKind::Parallel},
    {"health_scan", StageKind::Mixed},
}};

double secondsBetween(StepProfile::Clock::time_point from, StepProfile::Clock::time_point to) {
  return std::chrono::duration<double>(to - from).count();
}
}  // namespace

const StageInfo& stageInfo(StepStage stage) { return kStageInfo[static_cast<std::size_t>(stage)]; }

std::string_view stageKindName(StageKind kind) {
  switch (kind) {
    case StageKind::Serial: return "serial";
    case StageKind::Parallel: return "parallel";
    case StageKind::Mixed: return "mixed";
  }
  return "";
}

void StepProfile::enable() {
  const RegionTotals sampled = regions_;  // the governor's running sums go on
  *this = StepProfile{};
  regions_ = sampled;
  on_ = true;
}

void StepProfile::beginStepNow() {
  inStep_ = true;
  sampleNext_ = false;
  regionPending_ = false;
  stepThreads_ = 1;
  stepStart_ = last_ = Clock::now();
}

void StepProfile::endStepNow() {
  if (on_) {
    const double seconds = secondsBetween(stepStart_, last_);  // ends at the last lap: the stages sum to it
    stepSeconds_ += seconds;
    threadStepSeconds_ += stepThreads_ * seconds;
    ++steps_;
  }
  inStep_ = false;
}

void StepProfile::lapNow(StepStage stage) {
  const Clock::time_point now = Clock::now();
  const double wall = secondsBetween(last_, now);
  last_ = now;
  StageTotals region;
  if (regionPending_) {
    // Each thread of the region worked slot.seconds of the stage's wall time and waited the rest
    // (at the region's end, or while the first thread ran the stage's serial parts).
    regionPending_ = false;
    const int threads = std::min<int>(regionThreads_, static_cast<int>(slots_.size()));
    threads_ = std::max(1, threads);
    stepThreads_ = std::max(stepThreads_, threads_);
    for (int t = 0; t < threads; ++t) {
      const double work = std::min(wall, slots_[static_cast<std::size_t>(t)].seconds);
      region.workSeconds += work;
      region.waitSeconds += wall - work;
    }
    region.threadSeconds = threads * wall;
    regions_.workSeconds += region.workSeconds;
    regions_.waitSeconds += region.waitSeconds;
    regions_.threadSeconds += region.threadSeconds;
  }
  if (!on_) return;
  StageTotals& totals = stages_[static_cast<std::size_t>(stage)];
  totals.seconds += wall;
  ++totals.calls;
  totals.workSeconds += region.workSeconds;
  totals.waitSeconds += region.waitSeconds;
  totals.threadSeconds += region.threadSeconds;
}

void StepProfile::beginRegion(int maxThreads) {
  if (slots_.size() < static_cast<std::size_t>(maxThreads)) slots_.resize(static_cast<std::size_t>(maxThreads));
  regionThreads_ = 0;
  regionPending_ = true;
}

double StepProfile::stagedSeconds() const {
  double sum = 0.0;
  for (const StageTotals& s : stages_) sum += s.seconds;
  return sum;
}

double StepProfile::serialShare() const {
  if (!(stepSeconds_ > 0)) return 0.0;
  double serial = 0.0;
  for (std::size_t s = 0; s < kStages; ++s)
    if (kStageInfo[s].kind == StageKind::Serial) serial += stages_[s].seconds;
  return serial / stepSeconds_;
}

double StepProfile::waitShare() const {
  if (!(stepSeconds_ > 0)) return 0.0;
  double wait = 0.0;
  for (const StageTotals& s : stages_) wait += s.waitSeconds;
  return wait / threadStepSeconds_;
}

}  // namespace wiggle
