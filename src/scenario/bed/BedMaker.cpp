#include "scenario/bed/BedMaker.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <numbers>
#include <optional>

#include "core/Format.h"
#include "core/Hash.h"
#include "core/Rng.h"
#include "core/StopSignal.h"
#include "io/AtomicFile.h"
#include "io/FileLock.h"
#include "io/StateFile.h"
#include "physics/PairKernel.h"
#include "scenario/bed/EngineSettings.h"
#include "scenario/bed/LammpsBed.h"

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
using Clock = std::chrono::steady_clock;

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

// The bed every carved bed of a config is cut from: the seed's, poured without an intruder.
const ClumpDef kNoIntruder{};

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

namespace {


// A bed in the making: the World and the maker's bookkeeping at a point where the maker can stop
// and later continue with the same bits as if it never had (the end of a settling or relaxing
// chunk). Saved in the cache directory beside the finished beds (bedPartialPath).
struct PartialBed {
  World world;
  BedStage stage = BedStage::Pouring;
  int batch = 0;               // batches poured so far
  std::uint64_t serial = 0;    // grains offered so far (the random streams' index)
  std::uint64_t steps = 0;     // steps of bed making so far
  std::uint64_t batchSteps = 0, batchLimit = 0;  // of the batch settling now
  double surface = 0.0;        // free surface when the last batch had settled
  std::vector<double> recent;  // relaxing: kinetic energy per grain of the last time unit's checks

  void save(BinaryWriter& out, const std::string& key) const {
    out.string(key);
    out.value(stage);
    out.value<std::int64_t>(batch);
    for (std::uint64_t v : {serial, steps, batchSteps, batchLimit}) out.value(v);
    out.value(surface);
    out.array(recent);
    world.save(out);
  }
};

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

// Called at every point where the making can stop and continue (PartialBed): saves it when due.
using BedSaver = std::function<void(const PartialBed&)>;

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

}  // namespace

std::string bedStatusLine(const BedStatus& s, double targetHeight) {
  return "[bed] " + std::string(choiceName(s.stage)) + " batch " + std::to_string(s.batch) + ", " + std::to_string(s.grains) +
         " grains, surface " + formatNumber(s.surface) + " / " + formatNumber(targetHeight) + ", t = " +
         formatNumber(s.time) + (s.stage == BedStage::Relaxing ? ", KE/grain " + formatNumber(s.kineticPerGrain) : "");
}

namespace {

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

}  // namespace

World makeBed(const RunConfig& config, const ClumpDef& clump, const BedProgress& progress) {
  const BedSaver noSaving = [](const PartialBed&) {};
  if (config.bed.cavity == BedCavity::Carved)
    return carveBed(config, clump, finishBed(config, kNoIntruder, startBed(config, kNoIntruder), progress, noSaving),
                    progress, noSaving);
  return finishBed(config, clump, startBed(config, clump), progress, noSaving);
}

std::string bedCacheDir(const RunConfig& config) {
  if (!config.bed.cacheDir.empty()) return config.bed.cacheDir;
  if (const char* env = std::getenv("WIGGLE_CACHE"); env && *env) return env;
  if (const char* home = std::getenv("HOME"); home && *home) return std::string(home) + "/.cache/wiggle";
  return "/tmp/wiggle-cache";
}

std::string bedCachePath(const RunConfig& config, const std::string& key) {
  return bedCacheDir(config) + "/bed-" + key + ".bin";
}

namespace {

struct BedFile {
  std::string key;
  World world;
};

BedFile readBedFile(const std::string& file, const std::string& name) {
  const StatePayload payload = parseStateFile(file, name, "bed");
  BinaryReader in(payload.bytes.data(), payload.bytes.size(), name, payload.version);
  std::string key = in.string();
  World world = World::load(in);
  if (!in.atEnd()) throw Error(name + " has trailing data");
  return {std::move(key), std::move(world)};
}

// bed.file: the bed in that file fitted to this config. What the particles and the intruder were
// made with must be this config's; the rest (contact, time step, engine) is set anew. A file that is
// not a wiggle state file is read as a LAMMPS data file (readLammpsBed), which holds particles only:
// this config's intruder goes in, and every contact starts with zero shear.
// bed.swap_intruder: the bed's held intruder replaced by `clump` at the same place, at rest; its
// contacts (and their history) are found afresh. Refused when a grain overlaps the new atoms by
// more than kSwapOverlap: a bed settled around another outline, not another surface of this one
// (a grain lodged between two touching atoms of one surface reaches 0.046 d past their tops,
// docs/SHAPES.md, and may meet an atom of the other there). Returns what the run's log and summary
// say of it.
constexpr double kSwapOverlap = 0.1;  // [d] twice that lodging depth
std::string swapIntruder(World& world, const ClumpDef& clump, const std::string& what) {
  const ClumpState at = world.intruder();
  const ParticleStore& s = world.particles();
  const double width = world.def().boxWidth;
  double deepest = 0.0;
  for (std::uint32_t g = 0; g < s.grainCount; ++g)
    for (std::size_t a = 0; a < clump.offsetX.size(); ++a) {
      const double dx = minimumImage(s.x[g] - (at.x + clump.offsetX[a]), width);
      const double dy = s.y[g] - (at.y + clump.offsetY[a]);
      deepest = std::max(deepest, s.radius[g] + clump.atomRadius - std::hypot(dx, dy));
    }
  if (deepest > kSwapOverlap)
    throw Error(what + "bed.swap_intruder: a grain overlaps this config's intruder by " + formatNumber(deepest) +
                " d, more than " + formatNumber(kSwapOverlap) + " d (the bed was made around another outline)");
  const std::size_t before = world.clump().offsetX.size();
  world.setIntruder(clump, at.x, at.y);
  return "bed.swap_intruder: the bed's intruder of " + std::to_string(before) + " atoms replaced by this config's " +
         std::to_string(clump.offsetX.size()) + "; the deepest overlap of a grain with them " + formatNumber(deepest) +
         " d; their contacts start afresh";
}

CachedBed pinnedBed(const RunConfig& config, const ClumpDef& clump) {
  const std::string& path = config.bed.file;
  if (!std::filesystem::is_regular_file(path)) throw Error("bed.file = " + path + ": no such file");
  const std::string file = readFile(path);
  if (!isStateFile(file)) {
    World world = readLammpsBed(file, "bed.file = " + path, config, clump);
    Hasher h;  // the key names the file's contents (summary.json's bed_key)
    h.addBytes(file.data(), file.size());
    return CachedBed{std::move(world), "lammps-" + h.hex(), path, true,
                     "bed.file: a LAMMPS data file, read with bed.lammps_types = \"" + config.bed.lammpsTypes +
                         "\"; it has no contact history: every contact starts with zero shear"};
  }
  BedFile bed = readBedFile(file, path);
  World& world = bed.world;
  const WorldDef& made = world.def();
  const std::string what = "bed.file = " + path + ": ";
  if (made.boxWidth != config.box.width)
    throw Error(what + "its box is " + formatNumber(made.boxWidth) + " d wide, box.width = " + formatNumber(config.box.width));
  if (made.massModel != config.grains.massModel) throw Error(what + "its grains have another grains.mass_model");
  const ClumpDef& held = world.clump();
  if (!world.hasIntruder()) throw Error(what + "it has no intruder");
  const bool sameAtoms = held.offsetX == clump.offsetX && held.offsetY == clump.offsetY && held.atomRadius == clump.atomRadius;
  if (!sameAtoms && !config.bed.swapIntruder)
    throw Error(what + "its intruder is not this config's (intruder.shape, vertices, angle or surface differ; "
                "bed.swap_intruder = true puts this config's in its place)");
  if (held.mass != clump.mass)
    throw Error(what + "its intruder's mass is " + formatNumber(held.mass) + ", this config's " + formatNumber(clump.mass));
  if (world.intruder().y != config.intruder.y0)
    throw Error(what + "its intruder is at y = " + formatNumber(world.intruder().y) + ", intruder.y0 = " +
                formatNumber(config.intruder.y0));
  world.setParameters(worldDefFor(config));
  std::string note;
  if (!sameAtoms) note = swapIntruder(world, clump, what) + "; ";
  world.setIntruderMass(clump.mass, clump.massShares, clump.inertia);  // this config's, whatever the file's were
  if (bed.key != bedKey(config, clump))
    note += "bed.file: running on the bed made for other parameters (key " + bed.key + "), with this config's contact, "
            "time step and engine settings";
  return CachedBed{std::move(world), bed.key, path, true, note};
}

}  // namespace

World parseCachedBed(const std::string& file, const std::string& name, const std::string& key) {
  BedFile bed = readBedFile(file, name);
  if (bed.key != key) throw Error(name + " holds a bed for other parameters");
  return std::move(bed.world);
}

std::string bedPartialPath(const RunConfig& config, const std::string& key) {
  return bedCacheDir(config) + "/bed-" + key + ".partial.bin";
}

std::string bedLockPath(const RunConfig& config, const std::string& key) {
  return bedCacheDir(config) + "/bed-" + key + ".lock";
}

namespace {

// What happened to the cache on the way to a bed, for CachedBed::note.
struct CacheNotes {
  std::string text;
  void add(const std::string& line) { text += (text.empty() ? "" : "; ") + line; }
};

// The finished bed of this key from the cache, when a valid one is there; a refused entry is noted
// (and will be made again, never trusted).
std::optional<World> cachedBed(const RunConfig& config, const std::string& key, CacheNotes& notes) {
  const std::string path = bedCachePath(config, key);
  if (!std::filesystem::exists(path)) return std::nullopt;
  try {
    World world = parseCachedBed(readFile(path), path, key);
    // A kill between writing the bed and removing its partial file leaves the partial behind; the
    // finished bed supersedes it.
    std::error_code ec;
    std::filesystem::remove(bedPartialPath(config, key), ec);
    return world;
  } catch (const Error& e) {
    notes.add(std::string("cached bed refused and rebuilt: ") + e.what());
    return std::nullopt;
  }
}

// Stores a finished bed in the cache and removes its partial file; a failure is noted, not fatal.
void storeBed(const RunConfig& config, const std::string& key, const World& world, CacheNotes& notes) {
  BinaryWriter out;
  out.string(key);
  world.save(out);
  try {
    writeStateFile(bedCachePath(config, key), "bed", out.bytes());
    std::error_code ec;
    std::filesystem::remove(bedPartialPath(config, key), ec);
  } catch (const Error& e) {
    notes.add(std::string("bed not cached: ") + e.what());
  }
}

// Makes the cache directory if missing; false (noted) when it cannot be made.
bool makeCacheDir(const RunConfig& config, CacheNotes& notes) {
  std::error_code ec;
  std::filesystem::create_directories(bedCacheDir(config), ec);
  if (ec) notes.add("bed not cached: cannot create " + bedCacheDir(config) + ": " + ec.message());
  return !ec;
}

// While one process makes the bed of a key, another that wants it waits and then loads it from the
// cache (two bed tasks of a sweep whose carved beds share a base bed, or two runs started at once).
// A cache directory that cannot hold the lock file (read-only) gets no lock: the bed is made
// unguarded, as it is then not cached either.
std::optional<FileLock> lockBedMaking(const RunConfig& config, const std::string& key, bool cacheWritable) {
  if (!cacheWritable) return std::nullopt;
  try {
    return std::optional<FileLock>(std::in_place, bedLockPath(config, key), false, true,
                                   "bed " + key + " is being made");
  } catch (const Error&) {
    return std::nullopt;
  }
}

// The bed of `key` from the cache, or made by `make` (told whether the cache is writable, and where
// to note what it met) and stored there. While one process makes a bed, another that wants it waits
// for it (bed-KEY.lock) and then reads it from the cache.
CachedBed cachedOrMade(const RunConfig& config, const std::string& key,
                       const std::function<World(bool cacheWritable, CacheNotes& notes)>& make) {
  const std::string path = bedCachePath(config, key);
  CacheNotes notes;
  if (auto world = cachedBed(config, key, notes)) return CachedBed{std::move(*world), key, path, true, notes.text};
  const bool cacheWritable = makeCacheDir(config, notes);
  const std::optional<FileLock> making = lockBedMaking(config, key, cacheWritable);
  if (making && notes.text.empty())  // made by another process while this one waited
    if (auto world = cachedBed(config, key, notes)) return CachedBed{std::move(*world), key, path, true, notes.text};
  World world = make(cacheWritable, notes);
  if (cacheWritable) storeBed(config, key, world, notes);
  return CachedBed{std::move(world), key, path, false, notes.text};
}

// A poured bed (around `clump`, or without an intruder when it has no atoms): continued from its
// partial file when there is one, saved every run.checkpoint_interval seconds and when
// SIGINT/SIGTERM asks to stop (if the caller holds a StopSignalGuard).
CachedBed obtainPouredBed(const RunConfig& config, const ClumpDef& clump, const std::string& key,
                          const BedProgress& progress) {
  return cachedOrMade(config, key, [&](bool cacheWritable, CacheNotes& notes) {
    const std::string partialPath = bedPartialPath(config, key);
    std::optional<PartialBed> start;
    if (std::filesystem::exists(partialPath)) {
      try {
        start.emplace(parsePartialBed(readFile(partialPath), partialPath, key));
      } catch (const Error& e) {
        notes.add(std::string("unfinished bed refused, starting afresh: ") + e.what());
      }
    }
    if (!start) start.emplace(startBed(config, clump));
    auto lastSave = Clock::now();
    const BedSaver save = [&](const PartialBed& p) {
      const int signal = stopSignalReceived();
      if (signal == 0 && std::chrono::duration<double>(Clock::now() - lastSave).count() < config.run.checkpointInterval)
        return;
      std::string saved = " (the cache directory is not writable: nothing saved)";
      if (cacheWritable) {
        BinaryWriter out;
        p.save(out, key);
        writeStateFile(partialPath, "bed-partial", out.bytes());
        lastSave = Clock::now();
        saved = "; saved in " + partialPath + ": the same command continues it";
      }
      if (signal != 0)
        throw Interrupted(signal, "interrupted by signal " + std::to_string(signal) + " while making the bed at t = " +
                                      std::to_string(static_cast<double>(p.steps) * config.run.dt) + saved);
    };
    return finishBed(config, clump, std::move(*start), progress, save);
  });
}

// bed.cavity = "carved": carveBed on the seed's bed without an intruder, which is obtained (from the
// cache, or made there) like any poured bed. The carving is not saved part-way: it is short, and an
// interrupted one is carved again from the cached base bed, with the same bits.
CachedBed obtainCarvedBed(const RunConfig& config, const ClumpDef& clump, const BedProgress& progress) {
  return cachedOrMade(config, bedKey(config, clump), [&](bool, CacheNotes& notes) {
    CachedBed base = obtainPouredBed(config, kNoIntruder, baseBedKey(config), progress);
    if (!base.note.empty()) notes.add("base bed: " + base.note);
    const BedSaver stopWhenAsked = [&](const PartialBed& bed) {
      if (const int signal = stopSignalReceived(); signal != 0)
        throw Interrupted(signal, "interrupted by signal " + std::to_string(signal) +
                                      " while relaxing the carved bed at t = " +
                                      std::to_string(static_cast<double>(bed.steps) * config.run.dt) +
                                      " (the same command carves it again from the cached base bed)");
    };
    return carveBed(config, clump, std::move(base.world), progress, stopWhenAsked);
  });
}

}  // namespace

CachedBed obtainBed(const RunConfig& config, const ClumpDef& clump, const BedProgress& progress) {
  if (!config.bed.file.empty()) return pinnedBed(config, clump);
  const RunConfig made = bedMakingConfig(config);
  const ClumpDef madeClump = bedMakingClump(config, clump);
  CachedBed bed = made.bed.cavity == BedCavity::Carved
                      ? obtainCarvedBed(made, madeClump, progress)
                      : obtainPouredBed(made, madeClump, bedKey(made, madeClump), progress);
  // The bed of another friction (bed.mu) or intruder mass (bed.intruder_mass): run with this
  // config's. summary.json's bed_key names the bed. The clump's masses are always this config's: a
  // bed file holds no moment of inertia for an intruder that did not turn.
  if (config.bed.mu >= 0.0) bed.world.setParameters(worldDefFor(config));
  bed.world.setIntruderMass(clump.mass, clump.massShares, clump.inertia);
  return bed;
}

}  // namespace wiggle
