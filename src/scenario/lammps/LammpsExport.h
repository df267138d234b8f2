#pragma once
// `wiggle export-lammps`: the same case as `wiggle run`, written as a LAMMPS data file and input
// deck, so that LAMMPS (Debian's `lmp`, 29 Sep 2021) can run it from the same settled bed
// (docs/LAMMPS-EXPORT.md). Conventions are those of tools/lammps_reference/ (which wiggle matches
// to round-off): units lj, dimension 2, atom_style sphere, pair gran/hertz/history, fix freeze on
// the base, fix enforce2d; the intruder follows the recipe of docs/PHYSICS.md §14: every intruder atom
// carries the clump's total mass M (so meff of an intruder contact is m M / (m + M), as in wiggle),
// no gravity on the atoms, `fix move variable` prescribes x(t) = x0 + A sin(2 pi t / T) and leaves
// y to be integrated, and `fix setforce` gives every atom the force F_contact,y - M g so all atoms
// accelerate together with the clump's acceleration.
//
// The same data files are read back as beds by LammpsBed.h (bed.file).
//
// What cannot be carried: the tangential contact history. A data file has no section for it, and
// LAMMPS restores it only from its own binary restart files. The deck therefore starts every
// existing contact with zero shear displacement (also what LAMMPS's `fix pour` beds would have
// after a `read_data`); `withoutContactHistory` gives the wiggle World that starts the same way.
#include <cstdint>
#include <string>

#include "io/RunConfig.h"
#include "physics/World.h"
#include "scenario/case/Case.h"

namespace wiggle {

struct LammpsDeck {
  std::string data;   // data.lammps: atoms, velocities (read_data, atom_style sphere)
  std::string input;  // in.wiggle: the deck
  std::uint64_t steps = 0;       // run length: run.duration / run.dt (override: lmp -var nsteps N)
  std::uint64_t atoms = 0;       // grains + base + intruder atoms
  std::uint32_t grains = 0;
};

// File names inside the export directory, and the trajectory file LAMMPS writes.
inline constexpr const char* kLammpsDataFile = "data.lammps";
inline constexpr const char* kLammpsInputFile = "in.wiggle";
inline constexpr const char* kLammpsTrajectoryFile = "trajectory.csv";

// The deck for `world` at the start of the run: intruder set, its Sinusoid motion with y free,
// clock at 0 (what runExperiment has just before its first step). Throws wiggle::Error when the
// world is not in that state (no intruder, another motion, clock not at 0).
LammpsDeck makeLammpsDeck(const World& world, const Case& run);

// Writes DIR/data.lammps and DIR/in.wiggle, each atomically; creates DIR.
void writeLammpsDeck(const std::string& dir, const LammpsDeck& deck);

// The world LAMMPS starts from after read_data: the same particles (x wrapped into [0, W) as in the
// data file), velocities, spins, intruder and motion, but no contact history. For comparing a
// LAMMPS run of the exported deck with wiggle step by step.
World withoutContactHistory(const World& world);

// The whole export of `world`, the case's bed as `wiggle run` starts it (scenario/run's startRun:
// the bed obtained, the drive started, t = 0): the deck written into `dir` (writeLammpsDeck), with
// the case as config.toml (as a run directory holds it, so that `wiggle rate DIR` reads the LAMMPS
// run's trajectory.csv by wiggle's rules). The world is handed in, not obtained here, so that this
// room stands below bed making, which reads the same files back (LammpsBed.h).
LammpsDeck exportLammps(const World& world, const Case& run, const std::string& dir);

}  // namespace wiggle
