#include "physics/ThreadGovernor.h"

#include <algorithm>
#include <cmath>

#include "core/Machine.h"

namespace wiggle {

double waitingShare(const StepProfile::RegionTotals& regions, int threads) {
  if (threads <= 1 || !(regions.threadSeconds > 0)) return 0.0;
  const double most = regions.threadSeconds * (threads - 1) / threads;
  return std::clamp(regions.waitSeconds / most, 0.0, 1.0);
}

int ThreadRule::next(int threads, int ceiling, const ThreadWindow& window) {
  sinceChange_ += window.seconds;
  const bool trial = std::exchange(trial_, false);
  if (threads > ceiling) {
    sinceChange_ = 0.0;
    reason_ = ThreadChangeReason::Ceiling;
    return ceiling;
  }
  if (threads > 1 && window.waitShare > kShedAbove) {
    // A retake that brought the waiting back: the core is still taken, so wait longer before the
    // next, and where idle cores were what made it try, stop trusting them until a retake holds.
    if (trial) {
      retryAfter_ = std::min(2.0 * retryAfter_, kLongestRetry);
      idleMisled_ |= trialOnIdle_;
    } else {
      retryAfter_ = kFirstRetry;
    }
    sinceChange_ = 0.0;
    reason_ = ThreadChangeReason::Waiting;
    return threads - 1;
  }
  if (trial) {  // the retake held
    retryAfter_ = kFirstRetry;
    idleMisled_ = false;
  }
  if (threads >= ceiling) return threads;
  // Idle cores say at once that the other process ended; without them (none idle, or a system that
  // does not say) only a trial can tell, and a process of lower priority may leave the cores busy
  // and yet the threads free to run: so a retake is tried then too, ever more rarely.
  const bool idle = window.idleCores >= kIdleToRetake && !idleMisled_;
  if (sinceChange_ < (idle ? kFirstRetry : retryAfter_)) return threads;
  const int more = idle ? std::max(1, static_cast<int>(std::floor(window.idleCores + 0.25))) : 1;
  trial_ = true;
  trialOnIdle_ = idle;
  sinceChange_ = 0.0;
  reason_ = idle ? ThreadChangeReason::IdleCore : ThreadChangeReason::Trial;
  return std::min(ceiling, threads + more);
}

int ThreadGovernor::beforeStep(std::uint64_t step, int ceiling, StepProfile& profile) {
  ceiling = std::max(1, ceiling);
  ceiling_ = ceiling;
  switch (policy_) {
    case ThreadPolicy::Fixed: threads_ = ceiling; return threads_;
    case ThreadPolicy::Scheduled: {
      int threads = ceiling;
      for (const auto& [from, count] : schedule_)
        if (step >= from) threads = std::clamp(count, 1, ceiling);
      if (threads_ != 0 && threads != threads_) change(step, threads, ThreadChangeReason::Scheduled);
      threads_ = threads;
      return threads_;
    }
    case ThreadPolicy::Adaptive: break;
  }
  if (threads_ == 0) {  // the first step: every thread the run may use
    threads_ = ceiling;
    start_ = Clock::now();
    startWindow(start_, profile);
  }
  threads_ = std::min(threads_, ceiling);
  sampling_ = ceiling > 1 && step % kSampleEvery == 0;
  if (sampling_ && threads_ > 1) profile.sampleNextStep();
  return threads_;
}

void ThreadGovernor::afterStep(std::uint64_t step, const StepProfile& profile) {
  if (policy_ != ThreadPolicy::Adaptive || !sampling_) return;
  ++samples_;
  const Clock::time_point now = lastSample_ = Clock::now();
  if (samples_ >= kWindowSamples && std::chrono::duration<double>(now - windowStart_).count() >= kWindowSeconds)
    endWindow(step, now, profile);
}

std::vector<double> ThreadGovernor::secondsAt() const {
  std::vector<double> seconds = secondsAt_;
  if (policy_ != ThreadPolicy::Adaptive || threads_ == 0 || ceiling_ <= 1) return seconds;
  if (seconds.size() <= static_cast<std::size_t>(threads_)) seconds.resize(threads_ + 1, 0.0);
  // The open window, to its last sampled step (not the time since, which may be no stepping at all).
  seconds[threads_] += std::chrono::duration<double>(lastSample_ - windowStart_).count();
  return seconds;
}

void ThreadGovernor::startWindow(Clock::time_point now, const StepProfile& profile) {
  windowStart_ = lastSample_ = now;
  windowRegions_ = profile.regionTotals();
  windowIdle_ = idleCpuSeconds();
  samples_ = 0;
}

void ThreadGovernor::endWindow(std::uint64_t step, Clock::time_point now, const StepProfile& profile) {
  ThreadWindow window;
  window.seconds = std::chrono::duration<double>(now - windowStart_).count();
  const StepProfile::RegionTotals& totals = profile.regionTotals();
  StepProfile::RegionTotals regions;
  regions.workSeconds = totals.workSeconds - windowRegions_.workSeconds;
  regions.waitSeconds = totals.waitSeconds - windowRegions_.waitSeconds;
  regions.threadSeconds = totals.threadSeconds - windowRegions_.threadSeconds;
  window.waitShare = waitingShare(regions, threads_);
  const double idle = idleCpuSeconds();
  if (idle >= 0.0 && windowIdle_ >= 0.0 && window.seconds > 0.0) window.idleCores = (idle - windowIdle_) / window.seconds;
  if (secondsAt_.size() <= static_cast<std::size_t>(threads_)) secondsAt_.resize(threads_ + 1, 0.0);
  secondsAt_[threads_] += window.seconds;
  const int next = rule_.next(threads_, ceiling_, window);
  if (next != threads_) change(step, next, rule_.reason());
  startWindow(now, profile);
}

void ThreadGovernor::change(std::uint64_t step, int to, ThreadChangeReason reason) {
  const double seconds = start_ == Clock::time_point{} ? 0.0 : std::chrono::duration<double>(Clock::now() - start_).count();
  changes_.push_back({seconds, step, threads_, to, reason});
  threads_ = to;
}

}  // namespace wiggle
