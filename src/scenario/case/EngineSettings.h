#pragma once
// The engine's parameters for a run config: in the case room because bed making (scenario/bed) and
// the LAMMPS bed reader (scenario/lammps, the room below bed) both build worlds with them.
#include "io/RunConfig.h"
#include "physics/World.h"

namespace wiggle {

// The engine parameters of a run config (everything but the particles).
WorldDef worldDefFor(const RunConfig& config);

}  // namespace wiggle
