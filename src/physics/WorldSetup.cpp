// Building a World and changing it between steps: its particles, its intruder, its parameters and
// its clock (World.h, "set-up"). The step itself is World.cpp; checks and the hash WorldChecks.cpp;
// save and load WorldPersistence.cpp.
#include <algorithm>
#include <cmath>
#include <string>

#include "core/Assert.h"
#include "core/Format.h"
#include "physics/ClumpTurn.h"
#include "physics/World.h"

namespace wiggle {

namespace {
void requireFinite(double v, const char* what) {
  if (!std::isfinite(v)) throw Error(std::string(what) + " is not a finite number");
}
}  // namespace

World::World(const WorldDef& def) : def_(def), kernels_(&forceKernels(defaultSimdLevel(), def.contact.law)) {
  requireFinite(def.boxWidth, "box width");
  if (def.boxWidth <= 0) throw Error("box width must be > 0, got " + formatNumber(def.boxWidth));
  if (!(def.dt > 0) || !std::isfinite(def.dt)) throw Error("time step must be > 0, got " + formatNumber(def.dt));
  if (!(def.density > 0) || !std::isfinite(def.density)) throw Error("density must be > 0");
  if (!std::isfinite(def.gravity) || def.gravity < 0) throw Error("gravity must be >= 0");
  const ContactParams& c = def.contact;
  if (!(c.kn > 0) || !(c.kt > 0) || !std::isfinite(c.kn) || !std::isfinite(c.kt))
    throw Error("contact stiffnesses kn, kt must be > 0");
  if (!(c.gammaN >= 0) || !(c.gammaT >= 0) || !(c.mu >= 0) || !std::isfinite(c.gammaN) ||
      !std::isfinite(c.gammaT) || !std::isfinite(c.mu))
    throw Error("contact damping and friction must be >= 0");
  if (!(def.skin > 0) || !(def.intruderSkin > 0.5 * def.skin))
    throw Error("neighbour skins must be > 0 and intruder_skin > skin / 2");
  if (def.healthInterval == 0 || def.sortInterval == 0) throw Error("intervals must be >= 1 step");
  if (!(def.maxOverlapRatio > 0) || !(def.referenceImpactSpeed > 0) || !(def.maxSpeedFactor > 1) ||
      !std::isfinite(def.maxOverlapRatio) || !std::isfinite(def.referenceImpactSpeed) ||
      !std::isfinite(def.maxSpeedFactor))
    throw Error("blow-up bounds must be finite, > 0 (the speed factor > 1)");
}

// ---------------------------------------------------------------- set-up

void World::invalidate() {
  if (pendingNewToOld_.empty()) {
    pendingNewToOld_.resize(store_.size());
    for (std::uint32_t i = 0; i < store_.size(); ++i) pendingNewToOld_[i] = i;
  }
  listsStale_ = true;
}

std::uint32_t World::addGrain(double x, double y, double radius, double vx, double vy, double omega) {
  requireFinite(x, "grain x");
  requireFinite(y, "grain y");
  requireFinite(vx, "grain vx");
  requireFinite(vy, "grain vy");
  requireFinite(omega, "grain omega");
  if (!(radius > 0) || !std::isfinite(radius)) throw Error("grain radius must be > 0, got " + formatNumber(radius));
  if (x < 0 || x >= def_.boxWidth)
    throw Error("grain at x = " + formatNumber(x) + " is outside the periodic box [0, " + formatNumber(def_.boxWidth) + ")");
  if (y < 0) throw Error("grain at y = " + formatNumber(y) + " is below the base (y = 0)");
  invalidate();
  const double mass = particleMass(def_.massModel, def_.density, radius);
  const double invInertia = 1.0 / (inertiaCoefficient(def_.massModel) * mass * radius * radius);
  // Grains come before the frozen base: insert at grainCount (only the short base tail moves).
  const std::uint32_t at = store_.grainCount;
  store_.append(x, y, vx, vy, omega, radius, mass, 1.0 / mass, invInertia, nextTag_++);
  if (at + 1 != store_.size()) {
    std::vector<std::uint32_t> order(store_.size());
    for (std::uint32_t k = 0; k < order.size(); ++k) order[k] = k < at ? k : (k == at ? store_.size() - 1 : k - 1);
    store_.permute(order);
  }
  pendingNewToOld_.insert(pendingNewToOld_.begin() + at, kNoOldIndex);
  ++store_.grainCount;
  return at;
}

void World::addFrozen(double x, double y, double radius) {
  requireFinite(x, "frozen particle x");
  requireFinite(y, "frozen particle y");
  if (!(radius > 0) || !std::isfinite(radius)) throw Error("frozen particle radius must be > 0");
  if (x < 0 || x >= def_.boxWidth)
    throw Error("frozen particle at x = " + formatNumber(x) + " is outside the periodic box");
  invalidate();
  const double mass = particleMass(def_.massModel, def_.density, radius);
  store_.append(x, y, 0.0, 0.0, 0.0, radius, mass, 0.0, 0.0, nextTag_++);
  pendingNewToOld_.push_back(kNoOldIndex);
}

void World::setIntruder(const ClumpDef& clump, double x, double y) {
  requireFinite(x, "intruder x");
  requireFinite(y, "intruder y");
  if (clump.offsetX.empty() || clump.offsetX.size() != clump.offsetY.size())
    throw Error("intruder needs at least one atom and as many x as y offsets");
  if (!(clump.mass > 0) || !std::isfinite(clump.mass)) throw Error("intruder mass must be > 0");
  if (clump.massShares == 0) throw Error("intruder mass shares must be >= 1");
  if (!(clump.atomRadius > 0)) throw Error("intruder atom radius must be > 0");
  for (std::size_t a = 0; a < clump.offsetX.size(); ++a) {
    requireFinite(clump.offsetX[a], "intruder atom offset");
    requireFinite(clump.offsetY[a], "intruder atom offset");
  }
  clump_ = clump;
  bodyOffsetX_ = clump.offsetX;
  bodyOffsetY_ = clump.offsetY;
  spin_ = ClumpSpin{};
  hasIntruder_ = true;
  clumpState_ = ClumpState{x, y, 0.0, 0.0, 0.0, 0.0};
  motion_ = ClumpMotion{};
  motion_.x0 = x;
  intruderPairs_ = IntruderPairs{};
  invalidate();
}

void World::setIntruderMotion(const ClumpMotion& motion) {
  if (!hasIntruder_) throw Error("set an intruder before its motion");
  if (motion.sinusoidal() && !(motion.period > 0)) throw Error("drive period must be > 0");
  if (motion.kind == HorizontalMotion::RampedSinusoid && !(motion.rampTime > 0 && std::isfinite(motion.rampTime)))
    throw Error("drive ramp time must be > 0 and finite");
  if (motion.kind == HorizontalMotion::Prescribed &&
      (!motion.prescribed || !(motion.peakSpeed > 0) || !std::isfinite(motion.peakSpeed)))
    throw Error("a prescribed drive needs its function and a peak speed > 0");
  requireFinite(motion.x0, "drive centre");
  requireFinite(motion.amplitude, "drive amplitude");
  requireFinite(motion.velocity, "drive velocity");
  if (motion.rotationFree && !(clump_.inertia > 0 && std::isfinite(clump_.inertia)))
    throw Error("a clump that turns needs a moment of inertia > 0");
  motion_ = motion;
  if (!motion_.rotationFree) spin_.omega = 0.0;
  if (!motion_.verticalFree) clumpState_.vy = 0.0;
  placeIntruder();
  prepared_ = false;  // the drive velocity enters the contact forces: re-evaluate them
}

void World::adoptParticleIds(const std::vector<std::uint32_t>& tags) {
  if (tags.size() != store_.size()) throw Error("adoptParticleIds: one id per particle is needed");
  std::vector<std::uint32_t> sorted = tags;
  std::sort(sorted.begin(), sorted.end());
  if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
    throw Error("adoptParticleIds: ids must be unique");
  if (!sorted.empty() && sorted.back() == std::numeric_limits<std::uint32_t>::max())
    throw Error("adoptParticleIds: an id is too large");
  store_.tag = tags;
  nextTag_ = sorted.empty() ? 0 : sorted.back() + 1;
  keepOrderAtFirstBuild_ = true;
}

void World::removeGrains(const std::vector<bool>& remove) {
  if (remove.size() != store_.grainCount) throw Error("removeGrains: one flag per grain expected");
  invalidate();
  std::vector<std::uint32_t> order;
  order.reserve(store_.size());
  std::uint32_t kept = 0;
  for (std::uint32_t i = 0; i < store_.grainCount; ++i)
    if (!remove[i]) {
      order.push_back(i);
      ++kept;
    }
  for (std::uint32_t i = store_.grainCount; i < store_.size(); ++i) order.push_back(i);
  std::vector<std::uint32_t> map(order.size());
  for (std::size_t k = 0; k < order.size(); ++k) map[k] = pendingNewToOld_[order[k]];
  store_.permute(order);
  store_.grainCount = kept;
  pendingNewToOld_.swap(map);
}

void World::resetClock() {
  step_ = 0;
  lastSortStep_ = 0;
  prepared_ = false;
  placeIntruder();
}

void World::clearContactHistory() {
  for (auto* v : {&list_.shearX, &list_.shearY, &intruderPairs_.shearX, &intruderPairs_.shearY})
    std::fill(v->begin(), v->end(), 0.0);
  prepared_ = false;  // forces from the unloaded springs before the next step
}

void World::setParameters(const WorldDef& def) {
  if (def.boxWidth != def_.boxWidth || def.massModel != def_.massModel || def.density != def_.density)
    throw Error("setParameters: the box width, mass model and density must stay those of the particles");
  def_ = def;
  kernels_ = &forceKernels(kernels_->level, def.contact.law);
  invalidate();
  prepared_ = false;
}

void World::setIntruderMass(double mass, std::uint32_t massShares, double inertia) {
  if (!hasIntruder_) throw Error("set an intruder before its mass");
  if (!(mass > 0) || !std::isfinite(mass)) throw Error("intruder mass must be > 0");
  if (massShares == 0) throw Error("intruder mass shares must be >= 1");
  if (!(inertia >= 0) || !std::isfinite(inertia)) throw Error("intruder moment of inertia must be >= 0");
  clump_.mass = mass;
  clump_.massShares = massShares;
  clump_.inertia = inertia;
  prepared_ = false;
}

void World::setIntruderSpin(double omega) {
  if (!hasIntruder_ || !motion_.rotationFree) throw Error("only a clump that may turn takes a spin");
  requireFinite(omega, "intruder spin");
  spin_.omega = omega;
  prepared_ = false;  // the atoms' velocities enter the contact forces
}

void World::scaleGrainVelocities(double factor) {
  requireFinite(factor, "velocity factor");
  ParticleStore& s = store_;
  for (std::uint32_t i = 0; i < s.grainCount; ++i) {
    s.vx[i] *= factor;
    s.vy[i] *= factor;
    s.omega[i] *= factor;
  }
  refreshKinematics();
  prepared_ = false;
}

}  // namespace wiggle
