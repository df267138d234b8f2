#include "scenario/BedMaker.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>

#include "core/Hash.h"
#include "core/Rng.h"
#include "io/AtomicFile.h"
#include "io/StateFile.h"

namespace wiggle {

namespace {

constexpr std::uint64_t kBedFormat = 4;  // bump when bed making or the engine's arithmetic changes (4: the contact kernel with fewer divisions and block-wise force sums)
constexpr std::uint64_t kStepsPerCheck = 1000;

// Does a grain of radius r at (x, y) overlap any intruder atom (or sit inside the clump, which
// the clump's interior guard atoms turn into an overlap)?
bool touchesClump(const ClumpDef& clump, double cx, double cy, double x, double y, double r) {
  const double reach = r + clump.atomRadius + 0.01;
  for (std::size_t a = 0; a < clump.offsetX.size(); ++a) {
    const double dx = x - (cx + clump.offsetX[a]);
    const double dy = y - (cy + clump.offsetY[a]);
    if (dx * dx + dy * dy < reach * reach) return true;
  }
  return false;
}

double totalMass(const World& world) {
  double mass = 0.0;
  for (std::uint32_t i = 0; i < world.grainCount(); ++i) mass += world.particles().mass[i];
  return mass;
}

}  // namespace

WorldDef worldDefFor(const RunConfig& config) {
  WorldDef def;
  def.boxWidth = config.box.width;
  def.dt = config.run.dt;
  def.massModel = config.grains.massModel;
  def.contact = config.contact;
  def.skin = config.engine.skin;
  def.intruderSkin = config.engine.intruderSkin;
  def.sortInterval = config.engine.sortInterval;
  return def;
}

std::string bedKey(const RunConfig& c, const ClumpDef& clump) {
  Hasher h;
  h.addValue(kBedFormat);
  h.addValue(kStateFormatVersion);
  for (double v : {c.box.width, c.box.bedHeight, c.grains.dMin, c.grains.dMax, c.contact.kn, c.contact.kt,
                   c.contact.gammaN, c.contact.gammaT, c.contact.mu, c.intruder.y0, c.bed.batchHeight,
                   c.bed.settleSpeed, c.bed.restEnergy, c.bed.maxTime, c.run.dt, c.engine.skin,
                   c.engine.intruderSkin, clump.atomRadius, clump.mass})
    h.addValue(v);
  h.addValue(c.box.seed);
  h.addValue(static_cast<std::uint8_t>(c.grains.massModel));
  h.addValue(c.engine.sortInterval);
  h.add(clump.offsetX);
  h.add(clump.offsetY);
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

World makeBed(const RunConfig& config, const ClumpDef& clump, const BedProgress& progress) {
  const double width = config.box.width;
  const double target = config.box.bedHeight;
  World world(worldDefFor(config));
  for (int i = 0; i < static_cast<int>(std::lround(width)); ++i) world.addFrozen(i + 0.5, 0.0, 0.5);
  const double cx = 0.5 * width, cy = config.intruder.y0;
  world.setIntruder(clump, cx, cy);

  // Each batch is a loose lattice (spacing above the largest diameter: no overlaps) starting one
  // spacing above the current surface, with small random velocities to break the lattice.
  const double dMin = config.grains.dMin, dMax = config.grains.dMax;
  const double spacing = 1.05 * dMax;
  const int perRow = std::max(1, static_cast<int>(std::floor(width / spacing)));
  const double rowPitch = width / perRow;
  const std::uint64_t seed = config.box.seed;
  std::uint64_t serial = 0;
  const double dt = config.run.dt;
  const auto maxSteps = static_cast<std::uint64_t>(config.bed.maxTime / dt);
  std::uint64_t steps = 0;
  BedStatus status;
  auto report = [&](const char* stage) {
    if (!progress) return;
    status.stage = stage;
    status.grains = world.grainCount();
    status.time = static_cast<double>(steps) * dt;
    progress(status);
  };

  double surface = freeSurfaceHeight(world);
  while (surface < target) {
    // Start above the highest grain (not the median surface): a new grain must never overlap one
    // left standing above the surface, or the overlap's repulsion blows the pile apart.
    double highest = 0.5;
    const ParticleStore& s = world.particles();
    for (std::uint32_t i = 0; i < s.grainCount; ++i) highest = std::max(highest, s.y[i] + s.radius[i]);
    const double yStart = highest + spacing;
    for (double y = yStart; y < yStart + config.bed.batchHeight; y += spacing) {
      for (int c = 0; c < perRow; ++c, ++serial) {
        const double d = dMin + (dMax - dMin) * uniform01(seed, RngStream::GrainDiameter, serial);
        const double jitter = 0.5 * (spacing - dMax) * (2.0 * uniform01(seed, RngStream::PourPosition, serial) - 1.0);
        const double x = (c + 0.5) * rowPitch + jitter;
        if (touchesClump(clump, cx, cy, x, y, 0.5 * d)) continue;
        const double vx = 0.2 * (uniform01(seed, RngStream::PourVelocity, serial, 0) - 0.5);
        const double vy = -0.2 * uniform01(seed, RngStream::PourVelocity, serial, 1);
        world.addGrain(x, y, 0.5 * d, vx, vy);
      }
    }
    ++status.batch;
    // Settle: until no grain is faster than settle_speed, or the time a grain needs to fall the
    // batch height and come to rest several times over.
    const double fallTime = std::sqrt(2.0 * (config.bed.batchHeight + surface) / world.def().gravity);
    const auto batchLimit = static_cast<std::uint64_t>((4.0 * fallTime + 10.0) / dt);
    for (std::uint64_t batchSteps = 0; batchSteps < batchLimit && steps < maxSteps;) {
      world.run(kStepsPerCheck);
      batchSteps += kStepsPerCheck;
      steps += kStepsPerCheck;
      // Settled enough to pour on: the root-mean-square grain speed (a few fast rattlers do not
      // hold the next batch back).
      const double meanMass = totalMass(world) / std::max<std::uint32_t>(1, world.grainCount());
      const double rmsSpeed = std::sqrt(2.0 * world.kineticEnergy() / std::max<std::uint32_t>(1, world.grainCount()) / meanMass);
      if (rmsSpeed < config.bed.settleSpeed) break;
      status.progress = std::min(0.9, 0.9 * surface / target);
      report("pouring");
    }
    surface = freeSurfaceHeight(world);
    status.surface = surface;
    report("pouring");
    if (steps >= maxSteps)
      throw Error("bed making did not reach box.bed_height = " + std::to_string(target) + " within bed.max_time = " +
                  std::to_string(config.bed.maxTime) + " (surface at " + std::to_string(surface) + ")");
  }

  // Level the surface at the target height, then relax to rest.
  std::vector<bool> remove(world.grainCount());
  const ParticleStore& s = world.particles();
  for (std::uint32_t i = 0; i < s.grainCount; ++i) remove[i] = s.y[i] > target;
  world.removeGrains(remove);
  status.surface = freeSurfaceHeight(world);
  // At rest means the kinetic energy per grain, averaged over the last time unit, is below the
  // threshold: a single reading can catch the bed's slowly damped elastic "breathing" at a
  // turning point, where it is near zero.
  const auto window = static_cast<std::size_t>(std::ceil(1.0 / (kStepsPerCheck * dt)));
  std::vector<double> recent;
  for (;;) {
    recent.push_back(world.kineticEnergy() / std::max<std::uint32_t>(1, world.grainCount()));
    if (recent.size() > window) recent.erase(recent.begin());
    double perGrain = 0.0;
    for (double e : recent) perGrain += e;
    perGrain /= static_cast<double>(recent.size());
    status.kineticPerGrain = perGrain;
    status.progress = 0.9 + 0.1 * std::clamp(std::log10(1e-2 / std::max(perGrain, 1e-300)) /
                                                 std::log10(1e-2 / config.bed.restEnergy), 0.0, 1.0);
    report("relaxing");
    if (recent.size() == window && perGrain < config.bed.restEnergy) break;
    if (steps >= maxSteps)
      throw Error("the bed did not come to rest (kinetic energy per grain " + std::to_string(perGrain) +
                  " > bed.rest_energy) within bed.max_time = " + std::to_string(config.bed.maxTime));
    world.run(kStepsPerCheck);
    steps += kStepsPerCheck;
  }
  return world;
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

World parseCachedBed(const std::string& file, const std::string& name, const std::string& key) {
  const std::string payload = parseStateFile(file, name, "bed");
  BinaryReader in(payload.data(), payload.size(), name);
  if (in.string() != key) throw Error(name + " holds a bed for other parameters");
  World world = World::load(in);
  if (!in.atEnd()) throw Error(name + " has trailing data");
  return world;
}

CachedBed obtainBed(const RunConfig& config, const ClumpDef& clump, const BedProgress& progress) {
  const std::string key = bedKey(config, clump);
  const std::string dir = bedCacheDir(config);
  const std::string path = bedCachePath(config, key);
  std::string note;
  if (std::filesystem::exists(path)) {
    try {
      return CachedBed{parseCachedBed(readFile(path), path, key), key, path, true, ""};
    } catch (const Error& e) {
      note = std::string("cached bed refused and rebuilt: ") + e.what();
    }
  }
  World world = makeBed(config, clump, progress);
  BinaryWriter out;
  out.string(key);
  world.save(out);
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  try {
    if (ec) throw Error("cannot create " + dir + ": " + ec.message());
    writeStateFile(path, "bed", out.bytes());
  } catch (const Error& e) {
    note += (note.empty() ? "" : "; ") + std::string("bed not cached: ") + e.what();
  }
  return CachedBed{std::move(world), key, path, false, note};
}

}  // namespace wiggle
