#pragma once
// LAMMPS text dump frames (what OVITO opens): grains type 1, frozen base type 2, intruder atoms
// type 3 (ids after the particles'). Columns: id type x y z radius vx vy fx fy. fx fy [m g]: a
// particle's total force of the step (contacts, and gravity for grains); an intruder atom's, the
// sum of its contact forces (gravity and the drive act on the clump as a whole).
#include <string>

#include "physics/World.h"

namespace wiggle {

std::string lammpsDumpFrame(const World& world);

}  // namespace wiggle
