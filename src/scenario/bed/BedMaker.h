#pragma once
// Making the granular bed (docs/PHYSICS.md §8): grains poured in batches around the held intruder, each batch
// left to settle, until the free surface reaches the target height; grains above it removed; then
// relaxed until the kinetic energy per grain is below bed.rest_energy (or bed.max_time is spent).
// With bed.cavity = "carved" the seed's bed is poured once without an intruder, and each
// intruder's bed is cut from it: the grains the intruder touches removed, then relaxed to rest.
// A bed depends only on its own parameters, so it is cached on disk under a key that hashes exactly
// those (bedKey); one bed serves every amplitude and period of a shape.
#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "core/BinaryStream.h"
#include "core/Choice.h"
#include "io/RunConfig.h"
#include "physics/World.h"
#include "scenario/bed/RandomPour.h"

namespace wiggle {

// The bed maker's stages: a batch poured, then left to settle, until the surface is reached; then
// the whole relaxed to rest. A partial bed's file stores the stage as its index: append only.
enum class BedStage : std::uint8_t { Pouring, Settling, Relaxing };
template <>
struct ChoiceNames<BedStage> {
  static constexpr std::array<std::string_view, 3> names{"pouring", "settling", "relaxing"};
};

struct BedStatus {
  BedStage stage = BedStage::Pouring;  // as reported: pouring (with its settling) or relaxing
  int batch = 0;             // batches poured so far
  std::uint32_t grains = 0;
  double surface = 0.0;      // free-surface height [d]
  double time = 0.0;         // simulated bed-making time [sqrt(d/g)]
  double kineticPerGrain = 0.0;  // [m g d]
  double progress = 0.0;     // rough fraction done, for the progress line
};
using BedProgress = std::function<void(const BedStatus&)>;

// The status as one line of text: "[bed] pouring batch 5, 4590 grains, surface 59.1 / 195, t = 33.8".
std::string bedStatusLine(const BedStatus& status, double targetHeight);

// Hex key of everything a bed depends on: box, seed, grains, contact, intruder clump and position,
// bed-making parameters (not bed.max_time, a bound only; bed.pour and its parameters only when
// pour = "random", and bed.relax_damping only when not 0, so a bed made as before those keys existed
// keeps its key), time step and
// engine settings, and the bed format version.
// A carved bed's key holds its base bed's key and the intruder's clump and position.
std::string bedKey(const RunConfig& config, const ClumpDef& clump);

// The key of the bed carved beds of this config are cut from (the seed's, without an intruder).
std::string baseBedKey(const RunConfig& config);

// The config a case's bed is made with: the case's own, or with bed.mu >= 0 the same poured with
// contact.mu = bed.mu (and bed.mu back at -1), so that its key, cache entry and bits are those of
// that friction's own bed; obtainBed then gives the bed the case's contact.mu to run with. Both
// keys above are the keys of this config's bed.
RunConfig bedMakingConfig(const RunConfig& config);

// The clump a case's bed is poured around: the case's own, or with bed.intruder_mass > 0 the same
// atoms of that mass (the held intruder's mass enters the pour through the contacts' meff), so that
// the bed is that mass's own; obtainBed then gives the bed's intruder the case's mass to run with.
ClumpDef bedMakingClump(const RunConfig& config, const ClumpDef& clump);

// Free-surface height: the median over 2-d-wide columns of the highest grain top in the column.
double freeSurfaceHeight(const World& world);

// Makes a bed from scratch (deterministic: same config, same bits, any thread count).
World makeBed(const RunConfig& config, const ClumpDef& clump, const BedProgress& progress = {});

struct CachedBed {
  World world;
  std::string key;
  std::string path;
  bool fromCache = false;
  std::string note;  // why a cache entry was not used, if one was found and refused
};

// The cache directory: config.bed.cacheDir, else $WIGGLE_CACHE, else $HOME/.cache/wiggle.
std::string bedCacheDir(const RunConfig& config);

// The cache file of the bed with this key.
std::string bedCachePath(const RunConfig& config, const std::string& key);

// The file of the bed with this key while it is being made (saved every run.checkpoint_interval
// seconds of wall time and on SIGINT/SIGTERM; removed once the bed is cached).
std::string bedPartialPath(const RunConfig& config, const std::string& key);

// The lock file a process holds while it makes the bed with this key (another that wants the bed
// waits on it, then loads the bed from the cache).
std::string bedLockPath(const RunConfig& config, const std::string& key);

// The bed in a cache file's bytes (`name` starts every error message); throws wiggle::Error when
// the file is truncated, corrupt, foreign or holds the bed of another key.
World parseCachedBed(const std::string& file, const std::string& name, const std::string& key);

// Loads the bed from the cache when a valid entry exists; otherwise makes it, continuing from the
// bed's partial file when there is one, and stores it (a carved bed is cut from its base bed, itself
// loaded or made and cached; a process that finds a bed being made by another waits for it). A
// corrupt or foreign entry is reported in `note` and rebuilt, never trusted. While a StopSignalGuard is alive, SIGINT/SIGTERM saves the bed
// in the making and throws wiggle::Error; the same call later continues it, with the same bits as
// a bed made in one go. With bed.file set, the bed is that file's, checked against the config and
// given its engine parameters (World::setParameters), never made; `note` says when it was made for
// other parameters.
CachedBed obtainBed(const RunConfig& config, const ClumpDef& clump, const BedProgress& progress = {});

// --- The maker's stages, for the bed cache (BedCache.cpp), which saves a bed in the making at the
// points where it can stop and continues it from there.

// The bed every carved bed of a config is cut from: the seed's, poured without an intruder.
inline const ClumpDef kNoIntruder{};

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

// The partial bed saved in `file` (its text; `name` for errors), for the parameters of `key`.
PartialBed parsePartialBed(const std::string& file, const std::string& name, const std::string& key);
// The empty box: its base row, the intruder (when `clump` has atoms) held at its place.
PartialBed startBed(const RunConfig& config, const ClumpDef& clump);

// Called at every point where the making can stop and continue (PartialBed): saves it when due.
using BedSaver = std::function<void(const PartialBed&)>;

// Carries a bed in the making through to the end: pouring and settling batches until the free
// surface reaches the target, levelling it there, relaxing to rest.
World finishBed(const RunConfig& config, const ClumpDef& clump, PartialBed p, const BedProgress& progress,
                const BedSaver& save);
// bed.cavity = "carved": the intruder's bed cut from `base` (its seed's bed without an intruder).
World carveBed(const RunConfig& config, const ClumpDef& clump, World base, const BedProgress& progress,
               const BedSaver& save);

}  // namespace wiggle
