#pragma once
// A clump that turns about its centre (ClumpMotion::rotationFree, docs/PHYSICS.md §6): where its atoms
// are at an angle, and the torque its contacts exert. World::step turns it; these are the sums.
#include <vector>

#include "physics/Intruder.h"
#include "physics/NeighbourList.h"

namespace wiggle {

// The atoms' offsets at `angle` [rad]: the body's offsets at angle 0 turned counter-clockwise.
void turnedOffsets(const std::vector<double>& bodyX, const std::vector<double>& bodyY, double angle,
                   std::vector<double>& x, std::vector<double>& y);

// The torque about the clump's centre of its pairs' forces, in list order: each atom gets the
// opposite of its grain's force at the atom's offset, and the tangential force's own moment on the
// atom (-r_atom x torque arm, as a grain partner gets it).
double clumpContactTorque(const ClumpDef& clump, const IntruderPairs& pairs);

// The farthest an atom lies from the centre [d]: how far an atom moves per radian turned.
double clumpReach(const ClumpDef& clump);

}  // namespace wiggle
