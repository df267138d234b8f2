// The bed cache (docs/PHYSICS.md §8): beds by key in bed.cache_dir, made once by
// one process while the others wait for it, a bed in the making saved and continued, carved beds cut
// from their seed's cached bed, and bed.file's pinned beds fitted to a config. Making itself is
// BedMaker.cpp.
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <optional>

#include "core/Format.h"
#include "core/Hash.h"
#include "core/StopSignal.h"
#include "io/AtomicFile.h"
#include "io/FileLock.h"
#include "io/StateFile.h"
#include "physics/PairKernel.h"
#include "scenario/bed/BedMaker.h"
#include "scenario/case/EngineSettings.h"
#include "scenario/lammps/LammpsBed.h"

namespace wiggle {

namespace {
using Clock = std::chrono::steady_clock;
}  // namespace

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
