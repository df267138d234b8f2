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
#include <cstdint>
#include <string>
#include <vector>

#include "physics/World.h"

namespace wiggle {

// A dump frame's columns, one entry per particle then per intruder atom (the frame's row order).
struct ParticleFrame {
  std::uint64_t step = 0;
  double time = 0.0;
  double boxWidth = 0.0;
  double yLo = 0.0, yHi = 1.0;    // the frame's y bounds: the particles' extent plus a diameter
  std::vector<std::uint64_t> id;  // the dump's ids: tag + 1; intruder atoms after the particles'
  std::vector<int> type;          // 1 grain, 2 frozen base, 3 intruder atom
  std::vector<double> x, y, radius, vx, vy, fx, fy, tqz;
};

// The frame of the world's current step, the one a dump writes (and the Python module hands out).
ParticleFrame particleFrame(const World& world);

// That frame as LAMMPS dump text (its numbers to 9 significant digits, velocities and forces to 6).
std::string lammpsDumpFrame(const World& world);

}  // namespace wiggle
