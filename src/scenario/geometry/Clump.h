#pragma once
// The engine's clump for an intruder (docs/PHYSICS.md §6, docs/SHAPES.md): its atoms (a shell along
// the outline, Shape.h, or a body of glued spheres filling it), its mass by the mass rule, the
// mass its contacts see (intruder.contact_mass) and its moment of inertia (intruder.rotation), all
// from the body of glued 0.5 d spheres the intruder stands for.
#include <cstdint>
#include <vector>

#include "io/RunConfig.h"
#include "physics/Intruder.h"
#include "physics/ParticleStore.h"
#include "scenario/geometry/Shape.h"

namespace wiggle {

// The default intruder mass (docs/PHYSICS.md §6): the disk outline's area pi 3.5^2 times the grain
// material's mass per area, (2/3) rho d for spheres (a sphere's mass over its disc area) or rho for discs.
double defaultIntruderMass(MassModel model, double density);  // [rho d^3]
// The body of glued spheres an outline is built of (docs/SHAPES.md, "Mass"): a hexagonal packing of
// touching spheres of radius atomRadius (rows along x, one sphere at the centre) of which every one
// lies inside the outline. Their centres, in the outline's frame.
std::vector<OutlinePoint> gluedSphereBody(const Shape& shape, double atomRadius = 0.25);
// The mass of the disk outline (diameter 7) built of glued atoms, gluedSphereBody of the disk, each
// atom with the grains' mass model and density. 151 atoms of radius 0.25: 9.88 rho d^3 as spheres
// (29.6 as discs).
double gluedDiskMass(MassModel model, double density, double atomRadius = 0.25);  // [rho d^3]
// How many spheres share the intruder's mass in its contacts' meff (ClumpDef::massShares,
// intruder.contact_mass): 1 for "body"; for "atom", the spheres of the body the intruder is built
// of, upright (then turned): its own atoms for intruder.surface = "lattice", else gluedSphereBody's,
// the body of glued spheres a shell stands for.
std::uint32_t contactMassShares(const IntruderDef& def);
// The intruder's moment of inertia about its centre when it may turn (intruder.rotation = "free"):
// its mass M spread evenly over the spheres of the body it is built of (as contactMassShares counts
// them), each a point M / n at its centre plus its own (2/5 for spheres, 1/2 for discs) (M / n) r^2.
double bodyInertia(const IntruderDef& def, double mass, MassModel model);
// def.mass when positive, else the one def.massRule names (the same for every shape).
double intruderMass(const IntruderDef& def, MassModel model, double density);

// The atoms an intruder definition asks for (intruder.surface): a shell built as clumpOptionsFor(def)
// says ("smooth", "glued"; buildClumpAtoms), or "lattice": the upright outline filled with touching
// spheres on a square lattice (its lowest row on the base, a column through the centre), turned
// with the outline, its outer boundary in order as the shell and the rest as guards
// (docs/SHAPES.md). Throws wiggle::Error when the outline cannot hold them. `shape` is makeShape(def).
ClumpAtoms clumpAtomsFor(const IntruderDef& def, const Shape& shape);

// The engine's clump for an intruder definition: atom offsets relative to the centroid and the mass,
// its atoms clumpAtomsFor(def). The second form takes the shape makeShape(def) already made.
ClumpDef makeClump(const IntruderDef& def, MassModel model, double density);
ClumpDef makeClump(const IntruderDef& def, const Shape& shape, MassModel model, double density);

}  // namespace wiggle
