#pragma once
// The random pour (bed.pour = "random", docs/PHYSICS.md §8): one batch of grains placed as LAMMPS's
// fix pour places them, and the overlap test against the held clump that both pours use.
#include <cstdint>
#include <vector>

#include "io/RunConfig.h"
#include "physics/Intruder.h"

namespace wiggle {

// One batch of the random pour (bed.pour = "random", docs/PHYSICS.md §8), as LAMMPS's fix pour
// places it: candidates at uniformly random positions in the region x in [0, W), y in
// [yLow, yLow + bed.batch_height] with yLow = highest + d_max, diameters uniform in [d_min, d_max],
// each kept unless it overlaps a grain kept before it (periodic in x) or an atom of the clump held
// at (W / 2, intruder.y0); until the kept grains' area reaches bed.pour_fraction x the region's area
// or 100 x the target count of candidates have been drawn. Candidate k draws from the random
// streams at index firstSerial + k, so a batch is a pure function of its arguments.
struct PouredGrain {
  double x = 0.0, y = 0.0, radius = 0.0;  // [d]
};
struct RandomBatch {
  std::vector<PouredGrain> grains;  // in the order they were kept
  double yLow = 0.0, yHigh = 0.0;   // the region's vertical extent (centres) [d]
  double targetArea = 0.0;          // bed.pour_fraction x the region's area [d^2]
  double area = 0.0;                // the kept grains' total area [d^2]
  std::uint64_t attempts = 0;       // candidates drawn (serial numbers used)
  std::uint64_t maxAttempts = 0;    // the bound on attempts
};
RandomBatch randomPourBatch(const RunConfig& config, const ClumpDef& clump, double highest, std::uint64_t firstSerial);

// Does a grain of radius r at (x, y) overlap any atom of the clump centred at (cx, cy) (or sit inside
// the clump, which the clump's interior guard atoms turn into an overlap)?
bool touchesClump(const ClumpDef& clump, double cx, double cy, double x, double y, double r);

}  // namespace wiggle
