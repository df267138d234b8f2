#pragma once
// What a case will cost and what getting its bed takes, before anything runs: `wiggle run --check`,
// a sweep's plan and dry run, its ETA before a case has finished, and `wiggle boundary --dry-run`
// all ask here (docs/SWEEPS.md, "Cost estimate").
#include <map>
#include <string>
#include <vector>

#include "io/RunConfig.h"
#include "physics/Intruder.h"

namespace wiggle {

// One place for the numbers; docs/SWEEPS.md quotes them and says how they were measured. The speed
// itself is not here: it is the committed cost table's (below) until this machine has its own.
struct CostModel {
  // How a pour spends its simulated time (sqrt(d/g)), by bed.pour: per nominal batch (bed.batch_height
  // of the final bed: falling and settling), and how many batches it pours per nominal one (a pour
  // packs each batch looser than the bed ends up). Measured from the bed makers' logs: the lattice
  // pours of the 60 x 195 d and 300 x 195 d beds (2026-11-22 and -24) took 14 batches, poured by
  // t = 99; the random pours of such beds 28 batches, by t = 225-245 (2026-11-28); of 60 x 50 d
  // beds (2026-11-28), the lattice pour 4 batches by t = 30, the random one 7 by t = 70.
  struct Pour {
    double timePerNominalBatch;
    double batchesPerNominalBatch;
  };
  static constexpr Pour latticePour{10.0, 1.4};
  static constexpr Pour randomPour{24.0, 2.8};
  static constexpr Pour pour(BedPour kind) { return kind == BedPour::Random ? randomPour : latticePour; }
  // The final relaxation to bed.rest_energy = 1e-6 grows with the bed: t = 6 (lattice) and about 4
  // (random) in 60 x 50 d beds, 40 (lattice) and about 13 and 27 (random) in 60 x 195 d ones, 126
  // (lattice) and 131 (random) in 300 x 195 d ones; this per unit of the bed's area (box.width x
  // box.bed_height, d^2) is their least-squares line through zero.
  static constexpr double relaxTimePerArea = 2.2e-3;
  // The relaxation of a carved bed (bed.cavity = "carved") after its cut, and of any bed with
  // bed.relax_damping > 0. Measured on the paper-depth preset (seed 7, one quiet core, 2026-11-25):
  // a cut relaxed in 152 s undamped (about 53 time units at 23 ns per particle-step), 16 s with
  // bed.relax_damping = 2 (about 5.6).
  static constexpr double carvedRelaxTime = 55.0;
  static constexpr double dampedRelaxTime = 6.0;
};

// The committed cost table, bench/costs.csv, as the build embedded it (CMakeLists.txt): the bench
// script's medians per bed and thread count on one named machine (docs/PERFORMANCE.md): wiggle's
// rows, at one thread (the figure every estimate starts from) and at more (how it scales).
struct CostTable {
  struct Row {
    double particles = 0.0;
    double nsPerParticleStep = 0.0;
  };
  std::vector<Row> rows;  // one thread, by particles, ascending
  std::map<int, std::vector<Row>> rowsAtThreads;  // two threads or more, by count, each by particles
  std::string machine;
  std::string source;
  // The one-thread figure for a bed of `particles`: linear between the table's beds, the smallest or
  // the largest bed's figure beyond them (a particle-step costs more once the arrays outgrow the caches).
  double nsPerParticleStep(double particles) const;
  // The largest thread count the table measured that is at most `threads` (1 when none is).
  int measuredThreads(int threads) const;
  // How much faster `threads` threads step a bed of `particles` than one, as the table measured it at
  // measuredThreads(threads): a count beyond the table's is not extrapolated (no faster than its largest).
  double speedUp(double particles, int threads) const;
};
// Parses the table's CSV text (columns as bench/costs.csv); throws Error naming what is wrong.
CostTable parseCostTable(const std::string& csv);
const CostTable& committedCostTable();

// The ns per particle-step the estimates use, and where it comes from: once this machine has
// recorded one-thread runs on this CPU, the median of the last ones (scenario/cost/SpeedRecord.h), of
// beds of the config's size when there are any; else the committed cost table's figure for the
// config's bed size.
struct SpeedBasis {
  double ns = 0.0;
  std::string source;  // for people: "the median of this machine's last 9 one-thread runs (PATH)"
};
SpeedBasis speedBasis(const RunConfig& config);

// How `threads` threads speed a bed of `particles` up over one core, by the committed table's
// measured scaling (CostTable::speedUp), and the words that say where it comes from ("" at one thread).
struct ThreadScaling {
  double speedUp = 1.0;
  std::string words;
};
ThreadScaling threadScaling(double particles, int threads);

// Grains plus the frozen base row (one per unit of width); the intruder's atoms are negligible.
double estimatedParticles(const RunConfig& config);
// Estimated wall seconds of a case's run phase (bed excluded) at `nsPerParticleStep`.
double estimatedRunSeconds(const RunConfig& config, double nsPerParticleStep);
// The simulated time of making the case's bed, in time units of the whole bed (a batch of the pour
// counts for the share of the final grains it holds); for a carved bed, the cut's relaxation, plus
// pouring its base bed when `withBase`.
double estimatedBedTime(const RunConfig& config, bool withBase = true);
// Estimated wall seconds of making the case's bed at `nsPerParticleStep`: estimatedBedTime's steps of
// the bed's particles.
double estimatedBedSeconds(const RunConfig& config, double nsPerParticleStep, bool withBase = true);

// Where a case's bed comes from (docs/PHYSICS.md §8): a pinned file (bed.file), the cache, or made
// now: poured around the intruder, or carved from its seed's base bed, itself poured first unless
// the cache holds it. The one reading of "pour the base, then carve" that the run's check and the
// sweep's plan print and cost.
struct BedPlan {
  enum class Source { File, Cached, Pour, Carve };
  Source source = Source::Pour;
  std::string key;          // the bed key ("" for a pinned file)
  std::string path;         // the cache file, or bed.file
  std::string baseKey;      // Carve: the base bed's key
  bool baseCached = false;  // Carve: whether the cache holds the base bed
};
BedPlan planBed(const RunConfig& config, const ClumpDef& clump);

}  // namespace wiggle
