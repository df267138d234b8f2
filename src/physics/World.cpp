#include "physics/World.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <type_traits>

#include "core/Assert.h"
#include "core/Format.h"
#include "physics/ClumpTurn.h"

#include <omp.h>

namespace wiggle {

namespace {

// The grains' hot arrays and World's records of them as raw pointers, for the passes over the grains.
struct GrainArrays {
  double *x, *y, *vx, *vy, *omega, *fx, *fy, *torque;
  const double *radius, *mass, *invMass, *invInertia;
  Kinematics* kinematics;
  const double *xAtBuild, *yAtBuild;
  const std::uint32_t *crossStart, *crossPair;
  const double *pairForceX, *pairForceY, *pairTorqueArm;
};

// Grains per stretch of a pass: the cross pairs of a stretch, then its lanes, while its arrays are
// still in the first-level cache.
constexpr std::uint32_t kGrainStretch = 512;

// A pass over grains [begin, end) (World::GrainPass says what it does, in that order); returns the
// largest squared displacement since the last list build when it tracks, else 0. The cross pairs
// go grain by grain; the rest is each grain's own arithmetic, which runs in lanes (no grain reads
// another's values; the same operations on the same values as one by one, so the same bits).
template <bool FinishForces, bool Kick, bool Start, bool Track>
double passOverGrainRange(const GrainArrays a, std::uint32_t begin, std::uint32_t end, double dt, double gravity) {
  const double halfDt = 0.5 * dt;
  double maxSq = 0.0;
  for (std::uint32_t first = begin; first < end; first += kGrainStretch) {
    const std::uint32_t last = std::min(end, first + kGrainStretch);
    if constexpr (FinishForces) {
      for (std::uint32_t i = first; i < last; ++i)
        for (std::uint32_t c = a.crossStart[i]; c < a.crossStart[i + 1]; ++c) {
          const std::uint32_t k = a.crossPair[c];
          a.fx[i] -= a.pairForceX[k];
          a.fy[i] -= a.pairForceY[k];
          a.torque[i] -= a.radius[i] * a.pairTorqueArm[k];
        }
    }
    // (A 64-bit index: with a 32-bit one, which could wrap, the compiler gathers and scatters.)
#pragma omp simd reduction(max : maxSq)
    for (std::size_t i = first; i < last; ++i) {
      const double fx = a.fx[i], torque = a.torque[i];
      double fy = a.fy[i];
      if constexpr (FinishForces) {
        fy -= a.mass[i] * gravity;
        a.fy[i] = fy;
      }
      double vx = a.vx[i], vy = a.vy[i], omega = a.omega[i];
      const double kick = halfDt * a.invMass[i], spin = halfDt * a.invInertia[i];
      if constexpr (Kick) {  // this step's second half
        vx += kick * fx;
        vy += kick * fy;
        omega += spin * torque;
      }
      if constexpr (Start) {  // the next step's first half, and its drift
        vx += kick * fx;
        vy += kick * fy;
        omega += spin * torque;
        const double x = a.x[i] + dt * vx;
        const double y = a.y[i] + dt * vy;
        a.x[i] = x;
        a.y[i] = y;
        if constexpr (Track) {
          a.kinematics[i] = Kinematics{x, y, vx, vy};
          const double dx = x - a.xAtBuild[i];
          const double dy = y - a.yAtBuild[i];
          maxSq = std::max(maxSq, dx * dx + dy * dy);
        }
      }
      if constexpr (Kick || Start) {
        a.vx[i] = vx;
        a.vy[i] = vy;
        a.omega[i] = omega;
      }
    }
  }
  return maxSq;
}

}  // namespace

void addIntruderPairForces(ParticleStore& s, ClumpState& state, const IntruderPairs& ip) {
  const std::uint32_t n = s.grainCount;
  double clumpFx = 0.0, clumpFy = 0.0;
  for (std::uint32_t p = 0; p < ip.size(); ++p) {
    const std::uint32_t g = ip.grain[p];
    if (g < n) {
      s.fx[g] += ip.forceX[p];
      s.fy[g] += ip.forceY[p];
      s.torque[g] -= s.radius[g] * ip.torqueArm[p];
    }
    clumpFx -= ip.forceX[p];
    clumpFy -= ip.forceY[p];
  }
  state.contactFx = clumpFx;
  state.contactFy = clumpFy;
}

double addIntruderContactForces(ParticleStore& s, const ClumpDef& clump, ClumpState& state, IntruderPairs& pairs,
                                const ContactParams params, double dt, double width, bool updateShear,
                                double overlapRatio) {
  const double excess = forceKernels(defaultSimdLevel(), params.law)
                            .intruderPairForces(s, clump, state, 0.0, pairs, params, dt, width, updateShear, overlapRatio);
  addIntruderPairForces(s, state, pairs);
  return excess;
}

// ---------------------------------------------------------------- the step

void World::run(std::uint64_t steps) {
  runWatchingIntruder(steps, [](const ClumpState&, std::uint64_t, double) {});
}

namespace {
// The governor's thread count for the parallel regions of one step, the run's own count after it
// (an exception included), so that whatever runs between steps sees the count the run was given.
class ThreadCountForStep {
 public:
  ThreadCountForStep(int threads, int ceiling) : ceiling_(ceiling), changed_(threads != ceiling) {
    if (changed_) omp_set_num_threads(threads);
  }
  ~ThreadCountForStep() {
    if (changed_) omp_set_num_threads(ceiling_);
  }
  ThreadCountForStep(const ThreadCountForStep&) = delete;
  ThreadCountForStep& operator=(const ThreadCountForStep&) = delete;

 private:
  int ceiling_;
  bool changed_;
};
}  // namespace

void World::step() { advance(false); }

// One velocity-Verlet step. Within run(), nothing looks at the grains between two steps, so the
// pass that ends a step (cross pairs, gravity, second half kick) also starts the next one (first
// half kick, drift): one pass over the grains instead of two, with the same operations on the same
// values, so the same bits. The step after such a pass starts with its grains already moved
// (grainsStarted_); the last step of run() ends whole, as step() always does.
void World::advance(bool startNextStep) {
  const int ceiling = omp_get_max_threads();
  const ThreadCountForStep threads(governor_.beforeStep(step_, ceiling, profile_), ceiling);
  profile_.beginStep();
  if (!prepared_) prepare();
  if (!grainsStarted_) startGrains();
  grainsStarted_ = false;
  startIntruder();
  ++step_;
  placeIntruder();
  const bool rebuild = listsStale_ || maxDisplacementSq_ > 0.25 * def_.skin * def_.skin;
  const bool rebuildIntruder = !rebuild && hasIntruder_ && intruderPairsStale();
  profile_.lap(StepStage::IntruderMotion);
  if (rebuild)
    rebuildNeighbours();
  else if (rebuildIntruder)
    rebuildIntruderPairs({});
  computeContactForces(true);
  // The full check is a scan of every particle: every healthInterval steps, and at once when the
  // force loop saw an overlap beyond the bound (a blow-up can open and close between two scans).
  // It needs the step's end, so a step it follows ends whole.
  const bool scan = overlapAlarm_ || step_ % def_.healthInterval == 0;
  grainsStarted_ = startNextStep && !scan;
  completeForces(true, grainsStarted_);
  if (scan) {
    checkHealth();
    profile_.lap(StepStage::HealthScan);
  }
  profile_.endStep();
  governor_.afterStep(step_, profile_);
}

void World::enableStepProfile(bool on) {
  if (on)
    profile_.enable();
  else
    profile_.disable();
}

void World::prepare() {
  checkTimeStep();
  placeIntruder();
  rebuildNeighbours();
  computeContactForces(false);
  completeForces(false);
  prepared_ = true;
}

void World::placeIntruder() {
  if (!hasIntruder_) return;
  const ClumpMotion::Position p = motion_.at(time());
  if (motion_.kind == HorizontalMotion::Prescribed && !(std::isfinite(p.x) && std::fabs(p.vx) <= motion_.peakSpeed))
    throw Error("the prescribed drive gave x = " + formatNumber(p.x) + ", vx = " + formatNumber(p.vx) +
                " at t = " + formatNumber(time()) + ": x must be finite and |vx| at most its peak speed " +
                formatNumber(motion_.peakSpeed));
  clumpState_.x = p.x;
  clumpState_.vx = p.vx;
}

void World::startGrains() {
  maxDisplacementSq_ = passOverGrains(GrainPass{.start = true, .track = !listsStale_});
  profile_.lap(StepStage::StartGrains);
}

double World::passOverGrains(GrainPass pass) {
  ParticleStore& s = store_;
  const GrainArrays a{s.x.data(),
                      s.y.data(),
                      s.vx.data(),
                      s.vy.data(),
                      s.omega.data(),
                      s.fx.data(),
                      s.fy.data(),
                      s.torque.data(),
                      s.radius.data(),
                      s.mass.data(),
                      s.invMass.data(),
                      s.invInertia.data(),
                      kinematics_.data(),
                      xAtBuild_.data(),
                      yAtBuild_.data(),
                      list_.crossStart.data(),
                      list_.crossPair.data(),
                      list_.forceX.data(),
                      list_.forceY.data(),
                      list_.torqueArm.data()};
  // The four switches as template arguments, so that each pass's loop has no branch.
  using Range = double (*)(GrainArrays, std::uint32_t, std::uint32_t, double, double);
  const Range range = !pass.finishForces ? (pass.track ? &passOverGrainRange<false, false, true, true>
                                                       : &passOverGrainRange<false, false, true, false>)
                      : !pass.kick       ? &passOverGrainRange<true, false, false, false>
                      : !pass.start      ? &passOverGrainRange<true, true, false, false>
                      : pass.track       ? &passOverGrainRange<true, true, true, true>
                                         : &passOverGrainRange<true, true, true, false>;
  WIGGLE_ASSERT(pass.finishForces ? pass.kick || !pass.start : pass.start && !pass.kick);  // the passes above
  WIGGLE_ASSERT(!pass.track || pass.start);
  const std::uint32_t n = s.grainCount;
  const double dt = def_.dt, gravity = def_.gravity;
  double maxSq = 0.0;
  // Each thread the grains of its strip (NeighbourList::strip), whose force blocks it has just
  // evaluated; before the first list build, an even share.
  const bool byStrip = list_.rowCount() == n;
  const bool profiling = profile_.inStep();  // each thread's work, for the profile's wait (StepProfile)
  if (profiling) profile_.beginRegion(omp_get_max_threads());
#pragma omp parallel reduction(max : maxSq)
  {
    const StepProfile::Clock::time_point start =
        profiling ? StepProfile::Clock::now() : StepProfile::Clock::time_point{};
    const auto threads = static_cast<std::uint32_t>(omp_get_num_threads());
    const auto t = static_cast<std::uint32_t>(omp_get_thread_num());
    if (byStrip) {
      const NeighbourList::Strip strip = list_.strip(t, threads, firstThreadPairs());
      maxSq = range(a, strip.firstRow, strip.lastRow, dt, gravity);
    } else {
      maxSq = range(a, static_cast<std::uint32_t>(std::uint64_t{n} * t / threads),
                    static_cast<std::uint32_t>(std::uint64_t{n} * (t + 1) / threads), dt, gravity);
    }
    if (profiling) profile_.threadWorked(static_cast<int>(t), static_cast<int>(threads), start);
  }
  return maxSq;
}

std::uint32_t World::firstThreadPairs() const { return hasIntruder_ ? intruderPairs_.size() : 0; }

double World::stripImbalance(std::uint32_t threads) const { return list_.stripImbalance(threads, firstThreadPairs()); }

void World::kickIntruder() {
  clumpState_.vy += 0.5 * def_.dt * (clumpState_.contactFy - clump_.mass * def_.gravity) / clump_.mass;
}

void World::kickIntruderSpin() { spin_.omega += 0.5 * def_.dt * spin_.torque / clump_.inertia; }

void World::turnIntruder() { turnedOffsets(bodyOffsetX_, bodyOffsetY_, spin_.angle, clump_.offsetX, clump_.offsetY); }

void World::startIntruder() {
  if (hasIntruder_ && motion_.verticalFree) {
    kickIntruder();
    clumpState_.y += def_.dt * clumpState_.vy;
  }
  if (hasIntruder_ && motion_.rotationFree) {
    kickIntruderSpin();
    spin_.angle += def_.dt * spin_.omega;
    turnIntruder();
  }
}

void World::rebuildNeighbours() {
  ParticleStore& s = store_;
  const double width = def_.boxWidth;
  const auto grains = static_cast<std::int64_t>(s.grainCount);
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < grains; ++i) {
    // Grains move far less than a box width between rebuilds; the loops only guard blow-ups.
    while (s.x[i] < 0.0) s.x[i] += width;
    while (s.x[i] >= width) s.x[i] -= width;
  }
  std::vector<std::uint32_t> newToOld = std::move(pendingNewToOld_);
  pendingNewToOld_.clear();
  if (newToOld.empty()) {
    newToOld.resize(s.size());
    for (std::uint32_t i = 0; i < s.size(); ++i) newToOld[i] = i;
  }

  // Spatial re-sort of the grains (cells of about one diameter, row by row) keeps contact
  // partners close in memory. Done at deterministic steps only, so results stay reproducible.
  if ((rebuilds_ == 0 && !keepOrderAtFirstBuild_) || step_ >= lastSortStep_ + def_.sortInterval) {
    const double cell = 1.0;
    const auto columns = static_cast<std::uint64_t>(std::max(1.0, std::floor(width / cell)));
    std::vector<std::uint64_t> key(s.grainCount);
    double yMin = 0.0;
    for (std::uint32_t i = 0; i < s.grainCount; ++i) yMin = std::min(yMin, s.y[i]);
    for (std::uint32_t i = 0; i < s.grainCount; ++i) {
      const auto cx = std::min(columns - 1, static_cast<std::uint64_t>(s.x[i] / cell));
      const auto cy = static_cast<std::uint64_t>((s.y[i] - yMin) / cell);
      key[i] = cy * columns + cx;
    }
    std::vector<std::uint32_t> order(s.size());
    for (std::uint32_t i = 0; i < s.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.begin() + s.grainCount,
                     [&](std::uint32_t a, std::uint32_t b) { return key[a] < key[b]; });
    s.permute(order);
    std::vector<std::uint32_t> composed(s.size());
    for (std::uint32_t k = 0; k < s.size(); ++k) composed[k] = newToOld[order[k]];
    newToOld.swap(composed);
    lastSortStep_ = step_;
  }
  profile_.lap(StepStage::ListSort);

  // Built into the previous list's memory (its arrays keep their capacity): no allocation, no page
  // faults and no release of the old arrays on the one thread that would do them.
  spareList_.build(s, width, def_.skin, list_, newToOld);
  std::swap(list_, spareList_);
  profile_.lap(StepStage::ListBuild);
  xAtBuild_.assign(s.x.begin(), s.x.begin() + s.grainCount);
  yAtBuild_.assign(s.y.begin(), s.y.begin() + s.grainCount);
  maxDisplacementSq_ = 0.0;
  listsStale_ = false;
  ++rebuilds_;
  refreshKinematics();  // x was wrapped, grains may be re-sorted
  profile_.lap(StepStage::ListRefresh);
  if (hasIntruder_) rebuildIntruderPairs(newToOld);
}

void World::refreshKinematics() {
  const ParticleStore& s = store_;
  kinematics_.resize(s.size());
  const auto particles = static_cast<std::int64_t>(s.size());
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < particles; ++i) kinematics_[i] = Kinematics{s.x[i], s.y[i], s.vx[i], s.vy[i]};
}

bool World::intruderPairsStale() const {
  const double dx = clumpState_.x - clumpXAtBuild_;
  const double dy = clumpState_.y - clumpYAtBuild_;
  // A pair outside the list was farther than radI + radJ + intruderSkin at the build. Since then
  // the clump moved by |d| and the grain by at most skin/2 + (its displacement bound at the build).
  const double margin = def_.intruderSkin - 0.5 * def_.skin - grainDisplacementAtIntruderBuild_;
  if (motion_.rotationFree) {  // an atom moves by at most its distance from the centre times the turn
    const double moved = std::hypot(dx, dy) + clumpReach(clump_) * std::fabs(spin_.angle - clumpAngleAtBuild_);
    return moved > margin || margin <= 0.0;
  }
  return dx * dx + dy * dy > margin * margin || margin <= 0.0;
}

void World::rebuildIntruderPairs(const std::vector<std::uint32_t>& newToOld) {
  const ParticleStore& s = store_;
  const IntruderPairs old = std::move(intruderPairs_);
  intruderPairs_ = IntruderPairs{};
  IntruderPairs& pairs = intruderPairs_;
  const double width = def_.boxWidth, halfWidth = 0.5 * width;
  const double cx = clumpState_.x, cy = clumpState_.y;
  const double ra = clump_.atomRadius, skin = def_.intruderSkin;
  double minX = 0, maxX = 0, minY = 0, maxY = 0, rMax = 0;
  for (std::size_t a = 0; a < clump_.offsetX.size(); ++a) {
    minX = std::min(minX, clump_.offsetX[a]);
    maxX = std::max(maxX, clump_.offsetX[a]);
    minY = std::min(minY, clump_.offsetY[a]);
    maxY = std::max(maxY, clump_.offsetY[a]);
  }
  for (double r : s.radius) rMax = std::max(rMax, r);
  const double reach = rMax + ra + skin;
  for (std::uint32_t p = 0; p < s.size(); ++p) {
    double dx = s.x[p] - cx;
    if (dx > halfWidth) dx -= width;
    else if (dx < -halfWidth) dx += width;
    const double dy = s.y[p] - cy;
    if (dx < minX - reach || dx > maxX + reach || dy < minY - reach || dy > maxY + reach) continue;
    const std::uint32_t op = newToOld.empty() ? p : newToOld[p];
    // Old pairs are sorted by grain: find this grain's block once.
    auto first = op == kNoOldIndex ? old.grain.end() : std::lower_bound(old.grain.begin(), old.grain.end(), op);
    for (std::uint32_t a = 0; a < clump_.offsetX.size(); ++a) {
      const double ex = dx - clump_.offsetX[a];
      const double ey = dy - clump_.offsetY[a];
      const double cut = s.radius[p] + ra + skin;
      if (ex * ex + ey * ey >= cut * cut) continue;
      double hx = 0.0, hy = 0.0;
      for (auto it = first; it != old.grain.end() && *it == op; ++it) {
        const auto m = static_cast<std::size_t>(it - old.grain.begin());
        if (old.atom[m] == a) {
          hx = old.shearX[m];
          hy = old.shearY[m];
          break;
        }
      }
      pairs.grain.push_back(p);
      pairs.atom.push_back(a);
      pairs.shearX.push_back(hx);
      pairs.shearY.push_back(hy);
    }
  }
  pairs.forceX.assign(pairs.size(), 0.0);
  pairs.forceY.assign(pairs.size(), 0.0);
  pairs.torqueArm.assign(pairs.size(), 0.0);
  clumpXAtBuild_ = cx;
  clumpYAtBuild_ = cy;
  clumpAngleAtBuild_ = spin_.angle;
  grainDisplacementAtIntruderBuild_ = std::sqrt(maxDisplacementSq_);
  profile_.lap(StepStage::IntruderPairs);
}

void World::computeContactForces(bool updateShear) {
  ParticleStore& s = store_;
  NeighbourList& list = list_;
  const ContactParams params = def_.contact;
  const double dt = def_.dt;
  const double width = def_.boxWidth;
  // The force loop applies the detector's overlap bound itself: a blow-up that opens and closes
  // between two full scans still raises the alarm, and so a scan.
  const double overlapRatio = def_.maxOverlapRatio;

  // 1. Force blocks, each thread those of its strip (NeighbourList::strip; a block's sums do not
  //    depend on which thread evaluates it), and on the first thread, before its strip, the
  //    intruder's pairs: they read only positions and velocities, which no block writes, and write
  //    only their own slots; its strip is shorter by as many pairs. The largest overlap excess is a
  //    max: no dependence on the threads.
  double worstExcess = -std::numeric_limits<double>::infinity();
  const bool profiling = profile_.inStep();  // each thread's work, for the profile's wait (StepProfile)
  if (profiling) profile_.beginRegion(omp_get_max_threads());
#pragma omp parallel reduction(max : worstExcess)
  {
    const StepProfile::Clock::time_point start =
        profiling ? StepProfile::Clock::now() : StepProfile::Clock::time_point{};
    const auto threads = static_cast<std::uint32_t>(omp_get_num_threads());
    const auto t = static_cast<std::uint32_t>(omp_get_thread_num());
    if (t == 0 && hasIntruder_)
      worstExcess = std::max(worstExcess, kernels_->intruderPairForces(s, clump_, clumpState_,
                                                                       motion_.rotationFree ? spin_.omega : 0.0,
                                                                       intruderPairs_, params, dt, width, updateShear,
                                                                       overlapRatio));
    const NeighbourList::Strip strip = list.strip(t, threads, firstThreadPairs());
    for (std::uint32_t b = strip.firstBlock; b < strip.lastBlock; ++b)
      worstExcess = std::max(worstExcess, kernels_->forceBlock(b, s, kinematics_.data(), list, params, dt, width,
                                                               updateShear, overlapRatio));
    if (profiling) profile_.threadWorked(static_cast<int>(t), static_cast<int>(threads), start);
  }
  profile_.lap(StepStage::ContactForces);

  // 2. The intruder's pair forces onto its grains and the clump, serially in list order (after the
  //    blocks, which start their grains' sums from zero), so that no sum depends on the thread count.
  if (hasIntruder_) addIntruderPairForces(s, clumpState_, intruderPairs_);
  if (hasIntruder_ && motion_.rotationFree) spin_.torque = clumpContactTorque(clump_, intruderPairs_);
  overlapAlarm_ = worstExcess > 0.0;
  profile_.lap(StepStage::IntruderSums);
}

void World::completeForces(bool kick, bool startNextStep) {
  // 3. Cross pairs reach their partner grain, in pair order; then gravity; then, in a step, the
  //    second half kick (fused here: one pass over the grains instead of two), and when asked the
  //    next step's first half kick and drift (World::advance).
  const double maxSq = passOverGrains(
      GrainPass{.finishForces = true, .kick = kick, .start = startNextStep, .track = startNextStep && !listsStale_});
  if (startNextStep) maxDisplacementSq_ = maxSq;
  if (kick && hasIntruder_ && motion_.verticalFree) kickIntruder();
  if (kick && hasIntruder_ && motion_.rotationFree) kickIntruderSpin();
  profile_.lap(StepStage::CompleteForces);
}

}  // namespace wiggle
