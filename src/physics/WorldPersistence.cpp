// World::save and World::load: the whole dynamic state, field by field, so that a loaded world
// continues bit for bit. Kept apart from the step (World.cpp) because it changes for a different
// reason: the state file's layout (docs/RELIABILITY.md; the checkpoint and bed formats in
// scenario/run/Checkpoint and scenario/bed/BedMaker frame it with io/StateFile's magic, version and checksum).
// A field added to World is added here too, and the state format version is raised.
#include <cmath>
#include <cstdint>
#include <type_traits>

#include "core/Error.h"
#include "core/BinaryStream.h"
#include "physics/World.h"

namespace wiggle {

// The state format version (io/StateFile.h) that added the contact law after mu; older files hold
// Hertz worlds. (The physics floor does not include io: the number is restated here, and a
// round-trip test of a version-2 payload keeps the two in step.)
constexpr std::uint32_t kFirstFormatWithLaw = 3;
// The version that added the clump's mass shares (ClumpDef::massShares) at the end; older files
// hold clumps whose whole mass enters meff (1 share).
constexpr std::uint32_t kFirstFormatWithMassShares = 4;
// The version that added whether the clump may turn after the shares, and, when it may, its turn, its
// angle at the intruder pairs' build, its moment of inertia and its atoms' offsets at angle 0.
constexpr std::uint32_t kFirstFormatWithRotation = 5;

void World::save(BinaryWriter& out) const {
  if (motion_.kind == HorizontalMotion::Prescribed)
    throw Error(
        "a world driven by a prescribed function cannot be saved (the function is not data): "
        "give it a built-in drive first");
  out.value(def_.boxWidth);
  out.value(def_.dt);
  out.value(def_.gravity);
  out.value(def_.density);
  out.value(static_cast<std::uint8_t>(def_.massModel));
  out.value(def_.contact.kn);
  out.value(def_.contact.kt);
  out.value(def_.contact.gammaN);
  out.value(def_.contact.gammaT);
  out.value(def_.contact.mu);
  out.value(def_.contact.law);
  out.value(def_.skin);
  out.value(def_.intruderSkin);
  out.value(def_.sortInterval);
  out.value(def_.healthInterval);
  out.value(def_.maxOverlapRatio);
  out.value(def_.referenceImpactSpeed);
  out.value(def_.maxSpeedFactor);
  out.value(def_.minStepsPerContact);

  const ParticleStore& s = store_;
  out.value(s.grainCount);
  s.forEachArray([&out](const auto& values, ParticleStore::Hashed) { out.array(values); });

  out.array(list_.rowStart);
  out.array(list_.partner);
  out.array(list_.shearX);
  out.array(list_.shearY);
  out.array(intruderPairs_.grain);
  out.array(intruderPairs_.atom);
  out.array(intruderPairs_.shearX);
  out.array(intruderPairs_.shearY);

  out.value(static_cast<std::uint8_t>(hasIntruder_));
  out.array(clump_.offsetX);
  out.array(clump_.offsetY);
  out.value(clump_.atomRadius);
  out.value(clump_.mass);
  out.value(clumpState_.x);
  out.value(clumpState_.y);
  out.value(clumpState_.vx);
  out.value(clumpState_.vy);
  out.value(clumpState_.contactFx);
  out.value(clumpState_.contactFy);
  out.value(static_cast<std::uint8_t>(motion_.kind));
  out.value(motion_.x0);
  out.value(motion_.amplitude);
  out.value(motion_.period);
  out.value(motion_.velocity);
  out.value(static_cast<std::uint8_t>(motion_.verticalFree));
  // Only the ramped drive stores its ramp: files of the other motions keep their earlier layout.
  if (motion_.kind == HorizontalMotion::RampedSinusoid) out.value(motion_.rampTime);

  out.value(step_);
  out.value(rebuilds_);
  out.value(lastSortStep_);
  out.value(nextTag_);
  out.value(static_cast<std::uint8_t>(prepared_));
  out.value(static_cast<std::uint8_t>(listsStale_));
  out.array(xAtBuild_);
  out.array(yAtBuild_);
  out.value(maxDisplacementSq_);
  out.value(clumpXAtBuild_);
  out.value(clumpYAtBuild_);
  out.value(grainDisplacementAtIntruderBuild_);
  out.array(pendingNewToOld_);
  out.value(margins_.overlap);
  out.value(margins_.speed);
  out.value(clump_.massShares);
  out.value(static_cast<std::uint8_t>(motion_.rotationFree));
  if (motion_.rotationFree) {
    out.value(spin_.angle);
    out.value(spin_.omega);
    out.value(spin_.torque);
    out.value(clumpAngleAtBuild_);
    out.value(clump_.inertia);
    out.array(bodyOffsetX_);
    out.array(bodyOffsetY_);
  }
}

namespace {

// World::load's parts, in file order. Each reads its fields and checks them against what is
// already read, so a damaged file is refused with what is wrong rather than loaded.

WorldDef readDef(BinaryReader& in) {
  WorldDef def;
  def.boxWidth = in.value<double>();
  def.dt = in.value<double>();
  def.gravity = in.value<double>();
  def.density = in.value<double>();
  const auto massModel = in.value<std::uint8_t>();
  if (!isChoice<MassModel>(massModel)) throw Error(in.what() + " is corrupt: unknown mass model");
  def.massModel = static_cast<MassModel>(massModel);
  def.contact.kn = in.value<double>();
  def.contact.kt = in.value<double>();
  def.contact.gammaN = in.value<double>();
  def.contact.gammaT = in.value<double>();
  def.contact.mu = in.value<double>();
  if (in.formatVersion() >= kFirstFormatWithLaw) {
    const auto law = in.value<ContactLaw>();
    if (!isChoice<ContactLaw>(law)) throw Error(in.what() + " is corrupt: unknown contact law");
    def.contact.law = law;
  }
  def.skin = in.value<double>();
  def.intruderSkin = in.value<double>();
  def.sortInterval = in.value<std::uint64_t>();
  def.healthInterval = in.value<std::uint64_t>();
  def.maxOverlapRatio = in.value<double>();
  def.referenceImpactSpeed = in.value<double>();
  def.maxSpeedFactor = in.value<double>();
  def.minStepsPerContact = in.value<double>();
  return def;
}

void readParticles(BinaryReader& in, ParticleStore& s) {
  s.grainCount = in.value<std::uint32_t>();
  s.forEachArray([&in](auto& values, ParticleStore::Hashed) {
    values = in.array<typename std::remove_reference_t<decltype(values)>::value_type>();
  });
  const std::size_t n = s.x.size();
  s.forEachArray([&in, n](const auto& values, ParticleStore::Hashed) {
    if (values.size() != n) throw Error(in.what() + " is corrupt: particle arrays differ in length");
  });
  if (s.grainCount > n) throw Error(in.what() + " is corrupt: particle counts disagree");
}

// `particles`: the number of particles the partners must index.
void readNeighbourList(BinaryReader& in, NeighbourList& list, std::size_t particles, double boxWidth) {
  list.rowStart = in.array<std::uint32_t>();
  list.partner = in.array<std::uint32_t>();
  list.shearX = in.array<double>();
  list.shearY = in.array<double>();
  const std::size_t pairs = list.partner.size();
  // The stale flag is read later (World::load); a list saved stale (grains added or removed since
  // its build) may not match the grain count, and is rebuilt before use anyway.
  const bool neverBuilt = list.rowStart.empty() && pairs == 0;
  bool listOk = neverBuilt || (!list.rowStart.empty() && list.shearX.size() == pairs &&
                               list.shearY.size() == pairs && list.rowStart.front() == 0 &&
                               list.rowStart.back() == pairs);
  for (std::size_t i = 0; listOk && i + 1 < list.rowStart.size(); ++i)
    listOk = list.rowStart[i] <= list.rowStart[i + 1];
  for (std::size_t k = 0; listOk && k < pairs; ++k) listOk = list.partner[k] < particles;
  // Row i holds partners above i in ascending order: the force blocks rely on it (a pair only ever
  // adds to its own block's grains or, later, to a cross partner).
  for (std::size_t i = 0; listOk && i + 1 < list.rowStart.size(); ++i)
    for (std::uint32_t k = list.rowStart[i]; listOk && k < list.rowStart[i + 1]; ++k)
      listOk = list.partner[k] > i && (k == list.rowStart[i] || list.partner[k] > list.partner[k - 1]);
  if (!listOk) throw Error(in.what() + " is corrupt: the neighbour list is inconsistent");
  list.forceX.assign(pairs, 0.0);
  list.forceY.assign(pairs, 0.0);
  list.torqueArm.assign(pairs, 0.0);
  if (!neverBuilt) list.deriveIndex(forceBlockRows(boxWidth));
}

// The intruder's pairs, its clump, its state and its motion (pairs first, as saved; checked once the
// clump they index is read).
void readIntruder(BinaryReader& in, std::size_t particles, IntruderPairs& ip, bool& hasIntruder,
                  ClumpDef& clump, ClumpState& state, ClumpMotion& motion) {
  ip.grain = in.array<std::uint32_t>();
  ip.atom = in.array<std::uint32_t>();
  ip.shearX = in.array<double>();
  ip.shearY = in.array<double>();
  ip.forceX.assign(ip.grain.size(), 0.0);
  ip.forceY.assign(ip.grain.size(), 0.0);
  ip.torqueArm.assign(ip.grain.size(), 0.0);

  hasIntruder = in.value<std::uint8_t>() != 0;
  clump.offsetX = in.array<double>();
  clump.offsetY = in.array<double>();
  clump.atomRadius = in.value<double>();
  clump.mass = in.value<double>();
  if (ip.atom.size() != ip.grain.size() || ip.shearX.size() != ip.grain.size() ||
      ip.shearY.size() != ip.grain.size() || clump.offsetX.size() != clump.offsetY.size())
    throw Error(in.what() + " is corrupt: intruder arrays differ in length");
  for (std::size_t p = 0; p < ip.grain.size(); ++p)
    if (ip.grain[p] >= particles || ip.atom[p] >= clump.offsetX.size())
      throw Error(in.what() + " is corrupt: an intruder pair points outside the arrays");
  state.x = in.value<double>();
  state.y = in.value<double>();
  state.vx = in.value<double>();
  state.vy = in.value<double>();
  state.contactFx = in.value<double>();
  state.contactFy = in.value<double>();
  const auto kind = in.value<std::uint8_t>();
  if (kind > static_cast<std::uint8_t>(HorizontalMotion::VelocitySinusoid))
    throw Error(in.what() + " is corrupt: unknown intruder motion");
  motion.kind = static_cast<HorizontalMotion>(kind);
  motion.x0 = in.value<double>();
  motion.amplitude = in.value<double>();
  motion.period = in.value<double>();
  motion.velocity = in.value<double>();
  motion.verticalFree = in.value<std::uint8_t>() != 0;
  if (motion.kind == HorizontalMotion::RampedSinusoid) {
    motion.rampTime = in.value<double>();
    if (!(motion.rampTime > 0 && std::isfinite(motion.rampTime)))
      throw Error(in.what() + " is corrupt: a ramped drive without a ramp time");
  }
}

}  // namespace

World World::load(BinaryReader& in) {
  World w(readDef(in));
  ParticleStore& s = w.store_;
  readParticles(in, s);
  readNeighbourList(in, w.list_, s.x.size(), w.def_.boxWidth);
  readIntruder(in, s.x.size(), w.intruderPairs_, w.hasIntruder_, w.clump_, w.clumpState_, w.motion_);

  w.step_ = in.value<std::uint64_t>();
  w.rebuilds_ = in.value<std::uint64_t>();
  w.lastSortStep_ = in.value<std::uint64_t>();
  w.nextTag_ = in.value<std::uint32_t>();
  w.prepared_ = in.value<std::uint8_t>() != 0;
  w.listsStale_ = in.value<std::uint8_t>() != 0;
  if (!w.listsStale_ && w.list_.rowStart.size() != s.grainCount + 1)
    throw Error(in.what() + " is corrupt: the neighbour list does not match the grains");
  w.xAtBuild_ = in.array<double>();
  w.yAtBuild_ = in.array<double>();
  w.maxDisplacementSq_ = in.value<double>();
  w.clumpXAtBuild_ = in.value<double>();
  w.clumpYAtBuild_ = in.value<double>();
  w.grainDisplacementAtIntruderBuild_ = in.value<double>();
  w.pendingNewToOld_ = in.array<std::uint32_t>();
  w.margins_.overlap = in.value<double>();
  w.margins_.speed = in.value<double>();
  if (in.formatVersion() >= kFirstFormatWithMassShares) {
    w.clump_.massShares = in.value<std::uint32_t>();
    if (w.clump_.massShares == 0) throw Error(in.what() + " is corrupt: an intruder of 0 mass shares");
  }
  w.bodyOffsetX_ = w.clump_.offsetX;
  w.bodyOffsetY_ = w.clump_.offsetY;
  if (in.formatVersion() >= kFirstFormatWithRotation && in.value<std::uint8_t>() != 0) {
    w.motion_.rotationFree = true;
    w.spin_.angle = in.value<double>();
    w.spin_.omega = in.value<double>();
    w.spin_.torque = in.value<double>();
    w.clumpAngleAtBuild_ = in.value<double>();
    w.clump_.inertia = in.value<double>();
    w.bodyOffsetX_ = in.array<double>();
    w.bodyOffsetY_ = in.array<double>();
    if (w.bodyOffsetX_.size() != w.clump_.offsetX.size() || w.bodyOffsetY_.size() != w.clump_.offsetY.size() ||
        !(w.clump_.inertia > 0))
      throw Error(in.what() + " is corrupt: a turning intruder's body does not match its atoms");
  }
  if (!w.listsStale_ && (w.xAtBuild_.size() != s.grainCount || w.yAtBuild_.size() != s.grainCount))
    throw Error(in.what() + " is corrupt: build positions do not match the grains");
  w.refreshKinematics();
  return w;
}

}  // namespace wiggle
