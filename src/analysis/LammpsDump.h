#pragma once
// LAMMPS text dump frames (what OVITO opens): grains type 1, frozen base type 2, intruder atoms
// type 3 (ids after the particles'). Columns: id type x y z radius vx vy.
#include <string>

#include "physics/World.h"

namespace wiggle {

std::string lammpsDumpFrame(const World& world);

}  // namespace wiggle
