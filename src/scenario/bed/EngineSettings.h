#pragma once
// The engine's parameters for a run config: its own unit because bed making and the LAMMPS bed
// reader both build worlds with them (and neither may include the other).
#include "io/RunConfig.h"
#include "physics/World.h"

namespace wiggle {

// The engine parameters of a run config (everything but the particles).
WorldDef worldDefFor(const RunConfig& config);

}  // namespace wiggle
