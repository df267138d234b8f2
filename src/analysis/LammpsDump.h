#pragma once
// LAMMPS text dump frames (what OVITO opens): grains type 1, frozen base type 2, intruder atoms
// type 3 (ids after the particles'). Columns: id type x y z radius vx vy fx fy tqz.
//
// Forces [rho d^3 g] and torques [rho d^4 g] are those of the world's last force evaluation:
// a grain's total (its contacts, plus gravity), a base particle's or an intruder atom's contacts
// (the base is frozen; gravity and the drive act on the intruder as a whole), each torque about the
// particle's own centre. They are exact, and reproduced bit for bit by a resumed run, when the
// frame is written right after World::step() or World::evaluateForces(); not right after
// World::load, where the pairs' forces (which the base's and the atoms' sums read) are not restored.
#include <string>

#include "physics/World.h"

namespace wiggle {

std::string lammpsDumpFrame(const World& world);

}  // namespace wiggle
