#pragma once
// A LAMMPS data file read as a bed (bed.file): an exported bed (LammpsExport.h), or one that LAMMPS
// made (tools/validation/lammps_fix_pour.py), run by wiggle. In the LAMMPS room beside the writer of
// the same files, below bed making, which reads a pinned bed.file with it.
#include <string>

#include "io/RunConfig.h"
#include "physics/World.h"

namespace wiggle {

// bed.file = a LAMMPS data file: the bed in it for this config (atom_style sphere, as LAMMPS's
// write_data and writeLammpsDeck write it; `text` is the file's bytes). The atoms of the types that
// bed.lammps_types calls grain and base become grains (positions, velocities, spins) and frozen base
// particles, keeping their atom ids (World::adoptParticleIds); the drop types' atoms (the intruder
// the bed was made around) are left out and `clump` is held at the box centre and intruder.y0. A
// data file has no contact history, so every contact starts with zero shear. Throws wiggle::Error,
// one line starting with `name`, for what it cannot map: another atom style, a triclinic or tilted
// box, a box width that is not box.width, a type without a role, a grain density other than the
// config's, an atom off the z = 0 plane, a malformed number, a count the sections do not hold, or
// dropped atoms centred away from the config's intruder.
World readLammpsBed(const std::string& text, const std::string& name, const RunConfig& config, const ClumpDef& clump);

// x wrapped into [0, W) as World::rebuildNeighbours wraps it: what a data file holds, so that a bed
// read back and withoutContactHistory (LammpsExport.h) hold the very same bits.
double wrappedX(double x, double width);

}  // namespace wiggle
