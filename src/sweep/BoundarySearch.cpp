#include "sweep/BoundarySearch.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "core/Error.h"
#include "core/Format.h"

namespace wiggle {

namespace {
// A finer lattice is a typo: 100,000 values would be a grid no one runs.
constexpr int maxLatticeIntervals = 100000;
}  // namespace

void checkBoundaryOptions(const BoundaryOptions& o) {
  if (!std::isfinite(o.lo) || !std::isfinite(o.hi) || !(o.hi > o.lo))
    throw Error("the range must be LO:HI with LO < HI (it is " + formatNumber(o.lo) + ":" + formatNumber(o.hi) + ")");
  if (o.points < 2) throw Error("the coarse scan needs at least 2 points (it is " + std::to_string(o.points) + ")");
  if (!(o.resolution > 0) || !std::isfinite(o.resolution))
    throw Error("the resolution must be positive (it is " + formatNumber(o.resolution) + ")");
  const double intervals = (o.hi - o.lo) / o.resolution;
  if (intervals > maxLatticeIntervals)
    throw Error("the resolution " + formatNumber(o.resolution) + " is finer than the range / " +
                std::to_string(maxLatticeIntervals));
  if (intervals < (o.points - 1) * (1 - 1e-9))
    throw Error("the resolution " + formatNumber(o.resolution) + " is coarser than the scan's spacing " +
                formatNumber((o.hi - o.lo) / (o.points - 1)) + ": fewer points, or a finer resolution");
  if (o.minBeds < 2)
    throw Error("at least 2 beds per probe are needed for a standard error (minimum " + std::to_string(o.minBeds) +
                ")");
  if (o.maxBeds < o.minBeds)
    throw Error("the bed cap (" + std::to_string(o.maxBeds) + ") is below the minimum (" + std::to_string(o.minBeds) +
                ")");
  if (!(o.knownScatter >= 0) || !std::isfinite(o.knownScatter))
    throw Error("the known scatter must be zero or positive (it is " + formatNumber(o.knownScatter) + ")");
}

std::size_t latticeIntervals(const BoundaryOptions& o) {
  // A range of 10.0000000001 resolutions is 10 of them, not 11 with a last one of 1e-10.
  return static_cast<std::size_t>(std::ceil((o.hi - o.lo) / o.resolution - 1e-6));
}

double latticeValue(const BoundaryOptions& o, std::size_t index) {
  if (index >= latticeIntervals(o)) return o.hi;
  return std::stod(formatNumber(o.lo + static_cast<double>(index) * o.resolution, 12));
}

double studentT975(int dof) {
  static constexpr double table[] = {12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228,
                                     2.201,  2.179, 2.160, 2.145, 2.131, 2.120, 2.110, 2.101, 2.093, 2.086,
                                     2.080,  2.074, 2.069, 2.064, 2.060, 2.056, 2.052, 2.048, 2.045, 2.042};
  if (dof < 1) throw Error("Student's t needs at least one degree of freedom");
  return dof <= 30 ? table[dof - 1] : 1.960;
}

const char* verdictName(Verdict verdict) {
  switch (verdict) {
    case Verdict::Undecided: return "undecided";
    case Verdict::Rising: return "rising";
    case Verdict::Sinking: return "sinking";
    case Verdict::Neutral: return "neutral";
    case Verdict::Failed: return "failed";
  }
  return "?";
}

BoundarySearch::BoundarySearch(const BoundaryOptions& options) : options_(options) {
  checkBoundaryOptions(options_);
  const std::size_t n = latticeIntervals(options_);
  for (int k = 0; k < options_.points; ++k) {
    Probe p;
    p.index = static_cast<std::size_t>(std::llround(static_cast<double>(k) * n / (options_.points - 1)));
    p.value = latticeValue(options_, p.index);
    if (probes_.empty() || probes_.back().index != p.index) probes_.push_back(p);
  }
}

double BoundarySearch::sameValueTolerance() const {
  return 1e-12 * std::max(1.0, std::fabs(options_.hi - options_.lo));
}

Probe& BoundarySearch::probeAt(double value) {
  const double tolerance = sameValueTolerance();
  for (Probe& p : probes_)
    if (std::fabs(p.value - value) <= tolerance) return p;
  throw Error("boundary search: internal error: no probe at " + formatNumber(value, 17));
}

int BoundarySearch::bedsAsked(const Probe& p) const {
  // A new probe's first minBeds beds are independent: all are asked for at once; past them, one at
  // a time, as each decides whether the next is needed.
  return std::max(static_cast<int>(p.vy.size()) + 1, options_.minBeds);
}

void BoundarySearch::record(const BoundaryRun& run, double vy) {
  Probe& p = probeAt(run.value);
  if (p.failed) return;  // set aside: another bed of it failed in the same round
  if (p.verdict != Verdict::Undecided || run.seed <= static_cast<int>(p.vy.size()) || run.seed > bedsAsked(p) ||
      waiting_.count({p.index, run.seed}))
    throw Error("boundary search: internal error: bed " + std::to_string(run.seed) + " at " + formatNumber(run.value) +
                " was not asked for");
  waiting_[{p.index, run.seed}] = vy;
  // Beds join their probe in seed order, so what it decides does not depend on the order they arrive in.
  for (auto it = waiting_.find({p.index, static_cast<int>(p.vy.size()) + 1}); it != waiting_.end();
       it = waiting_.find({p.index, static_cast<int>(p.vy.size()) + 1})) {
    p.vy.push_back(it->second);
    waiting_.erase(it);
  }
  decide(p);
  refine();
}

void BoundarySearch::recordFailure(const BoundaryRun& run) {
  Probe& p = probeAt(run.value);
  p.failed = true;
  p.verdict = Verdict::Failed;
  refine();
}

void BoundarySearch::decide(Probe& p) const {
  const double n = static_cast<double>(p.vy.size());
  double sum = 0.0;
  for (const double v : p.vy) sum += v;
  p.mean = sum / n;
  double squares = 0.0;
  for (const double v : p.vy) squares += (v - p.mean) * (v - p.mean);
  const bool known = options_.knownScatter > 0;
  p.standardError = known              ? options_.knownScatter / std::sqrt(n)
                    : p.vy.size() >= 2 ? std::sqrt(squares / (n - 1) / n)
                                       : 0.0;
  const double t = known ? 1.960 : p.vy.size() >= 2 ? studentT975(static_cast<int>(p.vy.size()) - 1) : 0.0;
  if (static_cast<int>(p.vy.size()) >= options_.minBeds && std::fabs(p.mean) > t * p.standardError)
    p.verdict = p.mean > 0 ? Verdict::Rising : Verdict::Sinking;
  else if (static_cast<int>(p.vy.size()) >= options_.maxBeds)
    p.verdict = Verdict::Neutral;
}

void BoundarySearch::refine() {
  // Neighbours are the probes that have not failed; a pair is split once both are decided, at its
  // midpoint, or where that failed at a quarter (a bracket whose three points all failed stays as
  // it is, the failures reported).
  // The closure does not depend on the order results arrive in: each verdict is a function of its
  // own probe's results only.
  for (;;) {
    std::optional<std::size_t> split;
    const Probe* previous = nullptr;
    for (const Probe& p : probes_) {
      if (p.failed) continue;
      if (previous && previous->verdict != Verdict::Undecided && p.verdict != Verdict::Undecided &&
          previous->verdict != p.verdict && p.index - previous->index > 1) {
        const std::size_t a = previous->index, gap = p.index - a;
        for (const std::size_t at :
             {a + gap / 2, a + gap / 4, a + (3 * gap) / 4}) {  // past a failed midpoint, its quarters
          if (at > a && at < p.index &&
              std::none_of(probes_.begin(), probes_.end(), [&](const Probe& q) { return q.index == at; })) {
            split = at;
            break;
          }
        }
        if (split) break;
      }
      previous = &p;
    }
    if (!split) return;
    Probe middle;
    middle.index = *split;
    middle.value = latticeValue(options_, *split);
    probes_.insert(std::lower_bound(probes_.begin(), probes_.end(), *split,
                                    [](const Probe& q, std::size_t i) { return q.index < i; }),
                   middle);
  }
}

std::vector<BoundaryRun> BoundarySearch::next() const {
  std::vector<BoundaryRun> runs;
  for (const Probe& p : probes_)
    if (!p.failed && p.verdict == Verdict::Undecided)
      for (int seed = static_cast<int>(p.vy.size()) + 1; seed <= bedsAsked(p); ++seed)
        if (!waiting_.count({p.index, seed})) runs.push_back({p.value, seed});
  return runs;
}

std::vector<Crossing> BoundarySearch::crossings() const {
  std::vector<Crossing> out;
  const Probe* signedBefore = nullptr;
  std::optional<double> neutralLo, neutralHi;
  for (const Probe& p : probes_) {
    if (p.failed || p.verdict == Verdict::Undecided) continue;
    if (p.verdict == Verdict::Neutral) {
      if (!neutralLo) neutralLo = p.value;
      neutralHi = p.value;
      continue;
    }
    if (signedBefore && signedBefore->verdict != p.verdict)
      out.push_back({signedBefore->value, p.value, signedBefore->verdict, p.verdict, neutralLo, neutralHi});
    signedBefore = &p;
    neutralLo.reset();
    neutralHi.reset();
  }
  return out;
}

std::vector<NeutralBand> BoundarySearch::neutralBands() const {
  std::vector<NeutralBand> out;
  std::optional<double> signedBefore;
  for (const Probe& p : probes_) {
    if (p.failed || p.verdict == Verdict::Undecided) continue;
    if (p.verdict != Verdict::Neutral) {
      if (!out.empty() && !out.back().above) out.back().above = p.value;
      signedBefore = p.value;
    } else if (!out.empty() && !out.back().above) {
      out.back().last = p.value;
    } else {
      out.push_back({p.value, p.value, signedBefore, std::nullopt});
    }
  }
  return out;
}

}  // namespace wiggle
