// What the World checks and reports about itself, apart from the step: the time-step check against
// the contact time, the blow-up detector (docs/RELIABILITY.md, section 7), the kinetic energy,
// the state's size and its hash.
#include <algorithm>
#include <cmath>
#include <string>
#include <type_traits>

#include "core/Assert.h"
#include "core/Format.h"
#include "core/Hash.h"
#include "physics/World.h"

namespace wiggle {

// ---------------------------------------------------------------- checks

double World::peakDriveSpeed() const {
  if (!hasIntruder_) return 0.0;
  const double omega = motion_.omega();
  switch (motion_.kind) {
    case HorizontalMotion::Held: return 0.0;
    case HorizontalMotion::Sinusoid: return motion_.amplitude * omega;
    case HorizontalMotion::RampedSinusoid: return motion_.amplitude * (omega + 1.0 / motion_.rampTime);  // a bound
    case HorizontalMotion::ConstantVelocity: return std::fabs(motion_.velocity);
    case HorizontalMotion::VelocitySinusoid: return std::fabs(motion_.amplitude);
    case HorizontalMotion::Prescribed: return motion_.peakSpeed;
  }
  return 0.0;
}

double World::speedBound() const {
  return def_.maxSpeedFactor * std::max(def_.referenceImpactSpeed, peakDriveSpeed());
}

void World::checkTimeStep() const {
  const ParticleStore& s = store_;
  if (s.grainCount == 0) return;
  std::uint32_t lightest = 0;
  for (std::uint32_t i = 1; i < s.grainCount; ++i)
    if (s.mass[i] < s.mass[lightest]) lightest = i;
  const double speed = std::max(def_.referenceImpactSpeed, peakDriveSpeed());
  const double duration =
      contactLawTraits(def_.contact.law).contactTime(def_.contact, s.radius[lightest], s.mass[lightest], speed);
  const double limit = duration / def_.minStepsPerContact;
  if (def_.dt > limit)
    throw Error("run.dt = " + formatNumber(def_.dt) + " is too large: a " + std::string(choiceName(def_.contact.law)) +
                " contact between the lightest grains (d = " + formatNumber(2 * s.radius[lightest]) +
                ") at impact speed " + formatNumber(speed) + " lasts " + formatNumber(duration) +
                ", which needs dt <= " + formatNumber(limit) + " (" + formatNumber(def_.minStepsPerContact) +
                " steps per contact)");
}

// A pair's overlap and the most the detector allows it: maxOverlapRatio times the radius of the
// grain that reaches in (the smaller of two grains; the grain against the intruder). At a ratio of 1
// its centre would be at the other grain's surface or the intruder's outline, where the pair's
// normal no longer separates them and a grain can pass through.
struct PairOverlap {
  double overlap, allowed, boundRadius;
  bool tooDeep() const { return overlap > allowed; }
};

namespace {

bool grainFinite(const ParticleStore& s, std::uint32_t i) {
  return std::isfinite(s.x[i]) && std::isfinite(s.y[i]) && std::isfinite(s.vx[i]) && std::isfinite(s.vy[i]) &&
         std::isfinite(s.omega[i]);
}

double speedSq(const ParticleStore& s, std::uint32_t i) { return s.vx[i] * s.vx[i] + s.vy[i] * s.vy[i]; }

// Whether grain i fails the scan: a position or velocity not finite, below the base, or faster than
// the bound.
bool grainFails(const ParticleStore& s, std::uint32_t i, double maxSpeedSq) {
  return !grainFinite(s, i) || s.y[i] < 0.0 || speedSq(s, i) > maxSpeedSq;
}

// Two discs whose centres are (dx, dy) apart across the periodic box.
PairOverlap pairOverlap(double dx, double dy, double ri, double rj, double boundRadius, double width,
                        double ratio) {
  if (dx > 0.5 * width) dx -= width;
  else if (dx < -0.5 * width) dx += width;
  return {ri + rj - std::sqrt(dx * dx + dy * dy), ratio * boundRadius, boundRadius};
}

}  // namespace

// The full scan of the blow-up detector (docs/RELIABILITY.md, "The blow-up detector"). Each bound
// lies far beyond anything the model does when it is integrated correctly, however violent the
// drive: it stops a run whose numbers no longer mean anything, never a run that is merely extreme.
// The grains and the grain pairs are scanned by all threads: the margins are maxima and the verdict
// an "any", neither of which depends on the order, so they have the same bits at any thread count.
// A failed scan is done again in index order on one thread (checkHealthInOrder), which throws for
// the first offender, so the error names the same grain at any thread count.
void World::checkHealth() {
  const ParticleStore& s = store_;
  const double maxSpeed = speedBound(), maxSpeedSq = maxSpeed * maxSpeed;
  const std::uint32_t grains = s.grainCount, pairs = list_.pairCount();
  double fastestSq = 0.0, deepest = 0.0;
  bool failed = false;
#pragma omp parallel reduction(max : fastestSq, deepest) reduction(|| : failed)
  {
#pragma omp for schedule(static) nowait
    for (std::uint32_t i = 0; i < grains; ++i) {
      failed = failed || grainFails(s, i, maxSpeedSq);
      fastestSq = std::max(fastestSq, speedSq(s, i));
    }
#pragma omp for schedule(static)
    for (std::uint32_t k = 0; k < pairs; ++k) {
      const PairOverlap o = grainPairOverlap(k);
      failed = failed || o.tooDeep();
      deepest = std::max(deepest, o.overlap / o.allowed);
    }
  }
  if (hasIntruder_) {
    failed = failed || !std::isfinite(clumpState_.y) || !std::isfinite(clumpState_.vy);
    for (std::uint32_t p = 0; p < intruderPairs_.size(); ++p) {
      const PairOverlap o = intruderPairOverlap(p);
      failed = failed || o.tooDeep();
      deepest = std::max(deepest, o.overlap / o.allowed);
    }
  }
  if (failed) {
    checkHealthInOrder();
    WIGGLE_ASSERT(false && "the ordered scan found what the parallel one did");
  }
  margins_.speed = std::max(margins_.speed, std::sqrt(fastestSq) / maxSpeed);
  margins_.overlap = std::max(margins_.overlap, deepest);
}

PairOverlap World::grainPairOverlap(std::uint32_t k) const {
  const ParticleStore& s = store_;
  const std::uint32_t i = list_.owner[k], j = list_.partner[k];
  return pairOverlap(s.x[i] - s.x[j], s.y[i] - s.y[j], s.radius[i], s.radius[j], std::min(s.radius[i], s.radius[j]),
                     def_.boxWidth, def_.maxOverlapRatio);
}

PairOverlap World::intruderPairOverlap(std::uint32_t p) const {
  const ParticleStore& s = store_;
  const std::uint32_t g = intruderPairs_.grain[p], a = intruderPairs_.atom[p];
  return pairOverlap(s.x[g] - (clumpState_.x + clump_.offsetX[a]), s.y[g] - (clumpState_.y + clump_.offsetY[a]),
                     s.radius[g], clump_.atomRadius, s.radius[g], def_.boxWidth, def_.maxOverlapRatio);
}

void World::checkHealthInOrder() const {
  const ParticleStore& s = store_;
  const std::string at = "step " + std::to_string(step_) + " (t = " + formatNumber(time()) + "): ";
  const std::string cure = " (the simulation blew up: reduce run.dt)";
  const double maxSpeed = speedBound();
  for (std::uint32_t i = 0; i < s.grainCount; ++i) {
    if (!grainFails(s, i, maxSpeed * maxSpeed)) continue;
    const std::string grain = "grain " + std::to_string(s.tag[i]);
    if (!grainFinite(s, i)) throw SimulationError(at + grain + " has a non-finite position or velocity" + cure);
    if (s.y[i] < 0.0)
      throw SimulationError(at + grain + " fell through the base (y = " + formatNumber(s.y[i]) + ")" + cure);
    throw SimulationError(at + grain + " moves at " + formatNumber(std::sqrt(speedSq(s, i))) + " sqrt(g d), more than " +
                          formatNumber(def_.maxSpeedFactor) + " times the fastest the fall or the drive can make it (" +
                          formatNumber(maxSpeed / def_.maxSpeedFactor) + "): energy grew without a source" + cure);
  }
  auto throwIfTooDeep = [&](const PairOverlap& o, std::uint32_t grain, const char* what) {
    if (o.tooDeep())
      throw SimulationError(at + "grain " + std::to_string(s.tag[grain]) + " overlaps " + what + " by " +
                            formatNumber(o.overlap) + " d, more than " + formatNumber(def_.maxOverlapRatio) +
                            " of the radius " + formatNumber(o.boundRadius) + ": it is passing through" + cure);
  };
  for (std::uint32_t k = 0; k < list_.pairCount(); ++k)
    throwIfTooDeep(grainPairOverlap(k), list_.owner[k],
                   list_.partner[k] < s.grainCount ? "another grain" : "a base particle");
  if (!hasIntruder_) return;
  if (!std::isfinite(clumpState_.y) || !std::isfinite(clumpState_.vy))
    throw SimulationError(at + "the intruder's height or velocity is not finite" + cure);
  for (std::uint32_t p = 0; p < intruderPairs_.size(); ++p)
    throwIfTooDeep(intruderPairOverlap(p), intruderPairs_.grain[p], "the intruder");
}

// ---------------------------------------------------------------- observations

double World::kineticEnergy() const {
  // Serial on purpose: bed making compares it with a threshold, so its bits must not depend on
  // the thread count.
  const ParticleStore& s = store_;
  double energy = 0.0;
  for (std::uint32_t i = 0; i < s.grainCount; ++i) {
    const double inertia = 1.0 / s.invInertia[i];
    energy += 0.5 * s.mass[i] * (s.vx[i] * s.vx[i] + s.vy[i] * s.vy[i]) + 0.5 * inertia * s.omega[i] * s.omega[i];
  }
  return energy;
}

std::uint64_t World::touchingPairs() const {
  const ParticleStore& s = store_;
  const double width = def_.boxWidth, halfWidth = 0.5 * width;
  std::uint64_t touching = 0;
  for (std::uint32_t k = 0; k < list_.pairCount(); ++k) {
    const std::uint32_t i = list_.owner[k], j = list_.partner[k];
    double dx = s.x[i] - s.x[j];
    if (dx > halfWidth)
      dx -= width;
    else if (dx < -halfWidth)
      dx += width;
    const double dy = s.y[i] - s.y[j], reach = s.radius[i] + s.radius[j];
    touching += dx * dx + dy * dy < reach * reach;
  }
  return touching;
}

namespace {
template <class... Vectors>
std::size_t arrayBytes(const Vectors&... v) {
  return ((v.size() * sizeof(typename Vectors::value_type)) + ...);
}
}  // namespace

std::size_t World::stateBytes() const {
  const ParticleStore& s = store_;
  const NeighbourList& l = list_;
  const IntruderPairs& ip = intruderPairs_;
  std::size_t particleBytes = 0;
  s.forEachArray([&particleBytes](const auto& values, ParticleStore::Hashed) { particleBytes += arrayBytes(values); });
  return particleBytes + arrayBytes(kinematics_, xAtBuild_, yAtBuild_, pendingNewToOld_) +
         arrayBytes(l.rowStart, l.owner, l.partner, l.shearX, l.shearY, l.forceX, l.forceY, l.torqueArm,
                       l.crossStart, l.crossPair) +
         arrayBytes(ip.grain, ip.atom, ip.shearX, ip.shearY, ip.forceX, ip.forceY, ip.torqueArm, clump_.offsetX,
                       clump_.offsetY);
}

std::string World::stateHash() const {
  Hasher h;
  const ParticleStore& s = store_;
  h.addValue(step_);
  // The particles' identities first, then their hashed arrays in the store's order: the order every
  // committed state hash was computed in.
  h.add(s.tag);
  s.forEachArray([&h](const auto& values, ParticleStore::Hashed hashed) {
    if constexpr (std::is_same_v<std::decay_t<decltype(values)>, std::vector<double>>)
      if (hashed == ParticleStore::Hashed::Yes) h.add(values);
  });
  h.add(list_.partner);
  h.add(list_.shearX);
  h.add(list_.shearY);
  h.add(intruderPairs_.shearX);
  h.add(intruderPairs_.shearY);
  h.addValue(clumpState_);
  if (motion_.rotationFree) h.addValue(spin_);  // a clump that never turns keeps its runs' hashes
  return h.hex();
}


}  // namespace wiggle
