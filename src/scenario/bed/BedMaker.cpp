#include "scenario/bed/BedMaker.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/Format.h"
#include "core/Hash.h"
#include "core/Rng.h"
#include "io/StateFile.h"
#include "physics/PairKernel.h"
#include "scenario/case/EngineSettings.h"

namespace wiggle {

namespace {

constexpr std::uint64_t kBedFormat = 4;  // bump when bed making or the engine's arithmetic changes (4: the contact kernel with fewer divisions and block-wise force sums)
// The random pour's own format, in its beds' keys only (the lattice beds keep theirs): bump when it
// changes (2: grains start with fix pour's falling-stream speeds instead of all at bed.pour_speed).
constexpr std::uint64_t kRandomPourFormat = 2;
// Carved beds' own format, in their keys (which also hold their base bed's key): bump when carving
// changes.
constexpr std::uint64_t kCarvedFormat = 1;
constexpr std::uint64_t kStepsPerCheck = 1000;

double totalMass(const World& world) {
  double mass = 0.0;
  for (std::uint32_t i = 0; i < world.grainCount(); ++i) mass += world.particles().mass[i];
  return mass;
}

// The key of a bed poured around `clump` at intruder.y0, or, when `clump` has no atoms, of the
// seed's bed poured without an intruder (the base of carved beds: the same for every shape and y0).
std::string pouredBedKey(const RunConfig& c, const ClumpDef& clump) {
  // bed.max_time is left out on purpose: it only bounds the work, and a bed that completes is the
  // same bed whatever the bound (paper.toml and the benchmark share the paper bed this way).
  const bool intruder = !clump.offsetX.empty();
  Hasher h;
  h.addValue(kBedFormat);
  // The oldest state format this wiggle reads: a bed written in any format it reads keeps its key,
  // and the keys change (so that no bed is refused) only when that oldest format is dropped.
  h.addValue(kOldestStateFormatVersion);
  for (double v : {c.box.width, c.box.bedHeight, c.grains.dMin, c.grains.dMax, c.contact.kn, c.contact.kt,
                   c.contact.gammaN, c.contact.gammaT, c.contact.mu, intruder ? c.intruder.y0 : 0.0,
                   c.bed.batchHeight, c.bed.settleSpeed, c.bed.restEnergy, c.run.dt, c.engine.skin,
                   c.engine.intruderSkin, clump.atomRadius, clump.mass})
    h.addValue(v);
  h.addValue(c.box.seed);
  h.addValue(static_cast<std::uint8_t>(c.grains.massModel));
  h.addValue(c.engine.sortInterval);
  h.add(clump.offsetX);
  h.add(clump.offsetY);
  // The lattice pour hashes nothing more, so its beds keep the keys they had before bed.pour existed
  // (its bed ignores pour_fraction and pour_speed).
  if (c.bed.pour != BedPour::Lattice) {
    h.addValue(kRandomPourFormat);
    const std::string_view pour = choiceName(c.bed.pour);  // the name's bytes, as when it was a string
    h.addBytes(pour.data(), pour.size());
    h.addValue(c.bed.pourFraction);
    h.addValue(c.bed.pourSpeed);
  }
  if (c.bed.relaxDamping > 0) {  // likewise: an undamped bed keeps its key
    h.addBytes("relax_damping", 13);
    h.addValue(c.bed.relaxDamping);
  }
  if (c.contact.law != contactLaw<HertzLaw>) {  // likewise: a Hertz bed keeps its key
    h.addBytes("law", 3);
    h.addValue(c.contact.law);
  }
  if (clump.massShares != 1) {  // likewise: a bed poured around a body of one share keeps its key
    h.addBytes("mass shares", 11);
    h.addValue(clump.massShares);
  }
  if (!intruder) h.addBytes("no intruder", 11);
  return h.hex();
}

}  // namespace

RunConfig bedMakingConfig(const RunConfig& config) {
  RunConfig made = config;
  if (config.bed.mu >= 0.0) {
    made.contact.mu = config.bed.mu;
    made.bed.mu = -1.0;
  }
  if (config.bed.intruderMass > 0.0) {
    made.intruder.mass = config.bed.intruderMass;
    made.bed.intruderMass = 0.0;
  }
  return made;
}

ClumpDef bedMakingClump(const RunConfig& config, const ClumpDef& clump) {
  ClumpDef made = clump;
  if (config.bed.intruderMass > 0.0) made.mass = config.bed.intruderMass;
  return made;
}

std::string baseBedKey(const RunConfig& config) { return pouredBedKey(bedMakingConfig(config), kNoIntruder); }

std::string bedKey(const RunConfig& config, const ClumpDef& runClump) {
  const RunConfig c = bedMakingConfig(config);
  const ClumpDef clump = bedMakingClump(config, runClump);
  if (c.bed.cavity == BedCavity::Poured) return pouredBedKey(c, clump);
  Hasher h;
  h.addValue(kCarvedFormat);
  const std::string base = baseBedKey(c);
  h.addBytes(base.data(), base.size());
  for (double v : {c.intruder.y0, clump.atomRadius, clump.mass}) h.addValue(v);
  h.add(clump.offsetX);
  h.add(clump.offsetY);
  if (clump.massShares != 1) h.addValue(clump.massShares);
  return h.hex();
}

double freeSurfaceHeight(const World& world) {
  const ParticleStore& s = world.particles();
  const double width = world.def().boxWidth;
  const int columns = std::max(1, static_cast<int>(width / 2.0));
  std::vector<double> top(columns, 0.5);  // an empty column is at the base's top
  for (std::uint32_t i = 0; i < s.grainCount; ++i) {
    double x = std::fmod(s.x[i], width);
    if (x < 0) x += width;
    const int c = std::min(columns - 1, static_cast<int>(x / width * columns));
    top[c] = std::max(top[c], s.y[i] + s.radius[i]);
  }
  std::nth_element(top.begin(), top.begin() + columns / 2, top.end());
  return top[columns / 2];
}

PartialBed parsePartialBed(const std::string& file, const std::string& name, const std::string& key) {
  const StatePayload payload = parseStateFile(file, name, "bed-partial");
  BinaryReader in(payload.bytes.data(), payload.bytes.size(), name, payload.version);
  if (in.string() != key) throw Error(name + " holds a bed for other parameters");
  const auto stage = in.value<BedStage>();
  if (stage != BedStage::Settling && stage != BedStage::Relaxing) throw Error(name + " has an unknown stage");
  const auto batch = in.value<std::int64_t>();
  const auto serial = in.value<std::uint64_t>(), steps = in.value<std::uint64_t>();
  const auto batchSteps = in.value<std::uint64_t>(), batchLimit = in.value<std::uint64_t>();
  const auto surface = in.value<double>();
  std::vector<double> recent = in.array<double>(1u << 20);
  PartialBed p{World::load(in), stage, static_cast<int>(batch), serial, steps, batchSteps, batchLimit, surface,
               std::move(recent)};
  if (!in.atEnd()) throw Error(name + " has trailing data");
  if (batch < 0 || batch > (1 << 30)) throw Error(name + " has an impossible batch count");
  return p;
}

PartialBed startBed(const RunConfig& config, const ClumpDef& clump) {
  World world(worldDefFor(config));
  const double width = config.box.width;
  for (int i = 0; i < static_cast<int>(std::lround(width)); ++i) world.addFrozen(i + 0.5, 0.0, 0.5);
  if (!clump.offsetX.empty()) world.setIntruder(clump, 0.5 * width, config.intruder.y0);
  PartialBed p{std::move(world), BedStage::Pouring, 0, 0, 0, 0, 0, 0.0, {}};
  p.surface = freeSurfaceHeight(p.world);
  return p;
}

namespace {

// One batch of the lattice pour (below); a site that would overlap an intruder atom stays empty.
void pourLatticeBatch(const RunConfig& config, const ClumpDef& clump, PartialBed& p) {
  const double width = config.box.width;
  const double cx = 0.5 * width, cy = config.intruder.y0;
  const double dMin = config.grains.dMin, dMax = config.grains.dMax;
  const double spacing = 1.05 * dMax;
  const int perRow = std::max(1, static_cast<int>(std::floor(width / spacing)));
  const double rowPitch = width / perRow;
  const std::uint64_t seed = config.box.seed;
  // Start above the highest grain (not the median surface): a new grain must never overlap one
  // left standing above the surface, or the overlap's repulsion blows the pile apart.
  double highest = 0.5;
  const ParticleStore& s = p.world.particles();
  for (std::uint32_t i = 0; i < s.grainCount; ++i) highest = std::max(highest, s.y[i] + s.radius[i]);
  const double yStart = highest + spacing;
  for (double y = yStart; y < yStart + config.bed.batchHeight; y += spacing) {
    for (int c = 0; c < perRow; ++c, ++p.serial) {
      const double d = dMin + (dMax - dMin) * uniform01(seed, RngStream::GrainDiameter, p.serial);
      const double jitter = 0.5 * (spacing - dMax) * (2.0 * uniform01(seed, RngStream::PourPosition, p.serial) - 1.0);
      const double x = (c + 0.5) * rowPitch + jitter;
      if (touchesClump(clump, cx, cy, x, y, 0.5 * d)) continue;
      const double vx = 0.2 * (uniform01(seed, RngStream::PourVelocity, p.serial, 0) - 0.5);
      const double vy = -0.2 * uniform01(seed, RngStream::PourVelocity, p.serial, 1);
      p.world.addGrain(x, y, 0.5 * d, vx, vy);
    }
  }
}

// bed.pour = "lattice": each batch is a loose lattice (spacing above the largest diameter: no
// overlaps) starting one spacing above the highest grain, with small random velocities to break the
// lattice. bed.pour = "random": randomPourBatch, every grain moving down as if it had fallen from the
// top of the region with bed.pour_speed, as LAMMPS's fix pour sets it: the batch then falls as one
// continuous stream rather than as a block.
void pourBatch(const RunConfig& config, const ClumpDef& clump, PartialBed& p) {
  if (config.bed.pour == BedPour::Random) {
    double highest = 0.5;  // as the lattice finds it
    const ParticleStore& s = p.world.particles();
    for (std::uint32_t i = 0; i < s.grainCount; ++i) highest = std::max(highest, s.y[i] + s.radius[i]);
    const RandomBatch batch = randomPourBatch(config, clump, highest, p.serial);
    p.serial += batch.attempts;
    const double v0 = config.bed.pourSpeed, g2 = 2.0 * p.world.def().gravity;
    for (const PouredGrain& g : batch.grains)
      p.world.addGrain(g.x, g.y, g.radius, 0.0, -std::sqrt(v0 * v0 + g2 * (batch.yHigh - g.y)));
  } else {
    pourLatticeBatch(config, clump, p);
  }
  ++p.batch;
  // Settling ends when the rms grain speed is below settle_speed, or after the time a grain needs
  // to fall the batch height and come to rest several times over.
  const double fallTime = std::sqrt(2.0 * (config.bed.batchHeight + p.surface) / p.world.def().gravity);
  p.batchLimit = static_cast<std::uint64_t>((4.0 * fallTime + 10.0) / config.run.dt);
  p.batchSteps = 0;
}

// The grains whose centre lies above `height` (levelling the bed's surface there).
std::vector<bool> grainsAbove(const World& world, double height) {
  const ParticleStore& s = world.particles();
  std::vector<bool> above(world.grainCount());
  for (std::uint32_t i = 0; i < s.grainCount; ++i) above[i] = s.y[i] > height;
  return above;
}

}  // namespace

// Carries a bed in the making through to the end: pouring and settling batches until the free
// surface reaches the target, levelling it there, relaxing to rest.
World finishBed(const RunConfig& config, const ClumpDef& clump, PartialBed p, const BedProgress& progress,
                const BedSaver& save) {
  const double target = config.box.bedHeight;
  const double dt = config.run.dt;
  const auto maxSteps = static_cast<std::uint64_t>(config.bed.maxTime / dt);
  BedStatus status;
  auto report = [&](BedStage stage) {
    if (!progress) return;
    status.stage = stage;
    status.batch = p.batch;
    status.grains = p.world.grainCount();
    status.surface = p.surface;
    status.time = static_cast<double>(p.steps) * dt;
    progress(status);
  };
  // At rest means the kinetic energy per grain, averaged over the last time unit, is below the
  // threshold: a single reading can catch the bed's slowly damped elastic "breathing" at a
  // turning point, where it is near zero.
  const auto window = static_cast<std::size_t>(std::ceil(1.0 / (kStepsPerCheck * dt)));
  for (;;) {
    switch (p.stage) {
      case BedStage::Pouring:
        if (p.surface < target) {
          pourBatch(config, clump, p);
          p.stage = BedStage::Settling;
        } else {
          // A base bed (no intruder: bed.cavity = "carved") ends here, poured to the target: each
          // bed carved from it is levelled with its cut and relaxed once, held by its intruder.
          // Without an intruder nothing holds the bed in x, and it takes hundreds of time units to
          // come to rest (the paper-depth preset's was still above bed.rest_energy at t = 370, where
          // the bed poured around the disk rests at t = 115).
          if (!p.world.hasIntruder()) return std::move(p.world);
          // Level the surface at the target height, then relax to rest.
          p.world.removeGrains(grainsAbove(p.world, target));
          p.surface = freeSurfaceHeight(p.world);
          p.stage = BedStage::Relaxing;
        }
        break;
      case BedStage::Settling: {
        bool settled = p.batchSteps >= p.batchLimit || p.steps >= maxSteps;
        if (!settled) {
          p.world.run(kStepsPerCheck);
          p.batchSteps += kStepsPerCheck;
          p.steps += kStepsPerCheck;
          // Settled enough to pour on: the root-mean-square grain speed (a few fast rattlers do not
          // hold the next batch back).
          const double grains = std::max<std::uint32_t>(1, p.world.grainCount());
          const double meanMass = totalMass(p.world) / grains;
          settled = std::sqrt(2.0 * p.world.kineticEnergy() / grains / meanMass) < config.bed.settleSpeed;
        }
        if (!settled) {
          status.progress = std::min(0.9, 0.9 * p.surface / target);
          report(BedStage::Pouring);
          save(p);
          break;
        }
        p.surface = freeSurfaceHeight(p.world);
        report(BedStage::Pouring);
        if (p.steps >= maxSteps)
          throw Error("bed making did not reach box.bed_height = " + std::to_string(target) +
                      " within bed.max_time = " + std::to_string(config.bed.maxTime) + " (surface at " +
                      std::to_string(p.surface) + ")");
        p.stage = BedStage::Pouring;
        break;
      }
      case BedStage::Relaxing: {
        p.recent.push_back(p.world.kineticEnergy() / std::max<std::uint32_t>(1, p.world.grainCount()));
        if (p.recent.size() > window) p.recent.erase(p.recent.begin());
        double perGrain = 0.0;
        for (double e : p.recent) perGrain += e;
        perGrain /= static_cast<double>(p.recent.size());
        status.kineticPerGrain = perGrain;
        status.progress = 0.9 + 0.1 * std::clamp(std::log10(1e-2 / std::max(perGrain, 1e-300)) /
                                                     std::log10(1e-2 / config.bed.restEnergy), 0.0, 1.0);
        report(BedStage::Relaxing);
        if (p.recent.size() == window && perGrain < config.bed.restEnergy) return std::move(p.world);
        if (p.steps >= maxSteps)
          throw Error("the bed did not come to rest (kinetic energy per grain " + std::to_string(perGrain) +
                      " > bed.rest_energy) within bed.max_time = " + std::to_string(config.bed.maxTime));
        p.world.run(kStepsPerCheck);
        p.steps += kStepsPerCheck;
        if (config.bed.relaxDamping > 0)
          p.world.scaleGrainVelocities(std::exp(-config.bed.relaxDamping * static_cast<double>(kStepsPerCheck) * dt));
        save(p);
        break;
      }
    }
  }
}

std::string bedStatusLine(const BedStatus& s, double targetHeight) {
  return "[bed] " + std::string(choiceName(s.stage)) + " batch " + std::to_string(s.batch) + ", " + std::to_string(s.grains) +
         " grains, surface " + formatNumber(s.surface) + " / " + formatNumber(targetHeight) + ", t = " +
         formatNumber(s.time) + (s.stage == BedStage::Relaxing ? ", KE/grain " + formatNumber(s.kineticPerGrain) : "");
}

// bed.cavity = "carved": `base` (a bed poured without an intruder to box.bed_height) levelled as a
// poured bed is, the grains the intruder touches at (box centre, intruder.y0) removed with them,
// the intruder held there, and the bed relaxed to rest as a poured bed's last stage relaxes it.
World carveBed(const RunConfig& config, const ClumpDef& clump, World base, const BedProgress& progress,
               const BedSaver& save) {
  const double cx = 0.5 * config.box.width, cy = config.intruder.y0;
  const ParticleStore& s = base.particles();
  std::vector<bool> remove = grainsAbove(base, config.box.bedHeight);
  for (std::uint32_t i = 0; i < s.grainCount; ++i)
    remove[i] = remove[i] || touchesClump(clump, cx, cy, s.x[i], s.y[i], s.radius[i]);
  base.removeGrains(remove);
  base.setIntruder(clump, cx, cy);
  PartialBed p{std::move(base), BedStage::Relaxing, 0, 0, 0, 0, 0, 0.0, {}};
  p.surface = freeSurfaceHeight(p.world);
  return finishBed(config, clump, std::move(p), progress, save);
}

World makeBed(const RunConfig& config, const ClumpDef& clump, const BedProgress& progress) {
  const BedSaver noSaving = [](const PartialBed&) {};
  if (config.bed.cavity == BedCavity::Carved)
    return carveBed(config, clump, finishBed(config, kNoIntruder, startBed(config, kNoIntruder), progress, noSaving),
                    progress, noSaving);
  return finishBed(config, clump, startBed(config, clump), progress, noSaving);
}

}  // namespace wiggle
