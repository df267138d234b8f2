#pragma once
// Intruder shapes (docs/PHYSICS.md §6): the outline of each of the paper's shapes or of a user polygon, and the
// rigid clump of atoms (radius 0.25 d) that stands for it in the engine. docs/SHAPES.md explains
// the choices; the numbers quoted here are measured by tests/scenario/ShapeTest.cpp.
//
// Centre convention: the clump centre (the point whose trajectory x(t), y(t) is reported, and the
// point placed at intruder.y0) is the AREA CENTROID of the outline, i.e. the centre of mass of the
// uniformly filled shape, which is what LAMMPS reports (xcm) for a rigid body of equal atoms. For
// the disk, square and rectangles it is also the centre of the bounding box; for the apex-up
// triangle (side a, height H = a sqrt(3)/2) it lies H/3 above the base, not H/2. Rotation by
// intruder.angle is about this centre. A user polygon is shifted so that its centroid is at (0, 0).
#include <functional>
#include <string>
#include <vector>

#include "io/RunConfig.h"
#include "physics/Intruder.h"
#include "physics/ParticleStore.h"
#include "scenario/geometry/Polygon.h"

namespace wiggle {

// An outline in the clump frame: counter-clockwise, centroid at the origin, already rotated.
// Its name is choiceName(kind): the one table of shape names (ChoiceNames<ShapeName>, io/RunConfig.h).
struct Shape {
  ShapeName kind = ShapeName::Disk;
  Outline outline;       // [d]; a disk is a regular 720-gon with vertices at 0, 90, 180, 270 deg,
                         // so its top (+R), equator (y = 0) and height (2R) are exact
  double diskRadius = 0.0;  // [d], disk only
  // The disk is placed analytically (atoms on a circle), every other outline atom by atom.
  bool isDisk() const { return kind == ShapeName::Disk; }
};

// Every named shape: every ShapeName but Polygon, in the table's order. A shape added to
// ChoiceNames<ShapeName> joins it, and the tests that check every clump (tests/scenario/ShapeTest.cpp)
// check its clump too.
const std::vector<ShapeName>& namedShapes();

// The paper's five shapes, in the order OS1..OS5: the rows of its Table 1 (docs/paper-table1.json).
// A list of its own, not namedShapes(): a named shape the paper does not have stays out of `wiggle
// model`'s Table 1 and of the tests held to the paper's rows.
const std::vector<ShapeName>& paperShapes();

// Builds the outline of a shape (Polygon takes `vertices`, in any order and frame) rotated by
// angleDegrees counter-clockwise about its centroid. Throws wiggle::Error on a paper shape given
// vertices, or an invalid polygon (too few vertices, repeated vertices, zero area, non-finite
// numbers, self-intersection). A shape named in text is parsed where the text is read (the
// config, the command line) with choiceNamed<ShapeName>.
Shape makeShape(ShapeName kind, const Outline& vertices = {}, double angleDegrees = 0.0);
Shape makeShape(const IntruderDef& def);

// How deep a point lies inside a shape's outline [d] (negative outside): the disk's exact circle,
// else the polygon's (depthInside).
std::function<double(OutlinePoint)> depthFunction(const Shape& shape);


struct ClumpOptions {
  double atomRadius = 0.25;  // [d] spheres of diameter 0.5 (docs/PHYSICS.md §6)
  // Largest centre spacing of neighbouring surface atoms [d]. At 0.35 the outline stays within
  // 0.055 of the atoms, the cusps between atoms are 0.071 deep and a 0.9 grain sinks at most 0.022
  // into the surface (docs/SHAPES.md).
  double maxSpacing = 0.35;
  // At a convex corner too sharp for an atom touching both edges to come within this distance of
  // the tip, the corner atom slides toward the tip until it does (and then pokes out a little
  // beyond the edges) [d].
  double cornerGap = 0.09;
  // Interior "guard" atoms: they never touch a grain (the shell is closed), but they make any grain
  // centre placed inside the outline overlap an atom by >= guardMargin, so code that places grains
  // by checking overlaps with atoms alone can never put one inside a hollow clump.
  bool guardInterior = true;
  double guardSpacing = 0.9;  // lattice spacing of guard atoms [d]
  double guardMargin = 0.05;  // [d]
  double minGrainRadius = 0.45;  // smallest grain radius the guard and lodge checks assume [d]
};

struct ClumpAtoms {
  std::vector<OutlinePoint> surface;  // in order around the outline (neighbours are adjacent) [d]
  std::vector<OutlinePoint> guard;    // interior atoms [d]
  double atomRadius = 0.25;           // [d]
};

// The shell an intruder definition asks for (intruder.surface): "smooth", the defaults above;
// "glued", neighbouring surface atoms touching (maxSpacing = 2 atomRadius). ("lattice" places no
// shell: clumpAtomsFor.)
ClumpOptions clumpOptionsFor(const IntruderDef& def);

// Places the atoms for a shape (no validation; see measureClump / makeClump).
ClumpAtoms placeAtoms(const Shape& shape, const ClumpOptions& options = {});

// Expected deviation at a convex corner of interior angle `interiorAngle` [rad]: the larger of the
// gap between the tip and the corner atom and the corner atom's overshoot beyond the edges [d].
// 0.09 down to about 56 deg, 0.1 at 50.8 deg (the sharpest corner the 0.1 tolerance allows).
double cornerDeviation(double interiorAngle, const ClumpOptions& options = {});

// How well a clump's atoms represent its outline (all lengths in d).
struct ClumpQuality {
  std::size_t surfaceAtoms = 0, guardAtoms = 0;
  double maxOvershoot = 0.0;      // farthest any atom reaches beyond the outline
  double maxOutlineGap = 0.0;     // farthest any outline point is from the atoms' envelope
  double maxEnvelopeDepth = 0.0;  // deepest point of the outer envelope (cusps between atoms)
  double maxSurfaceSpacing = 0.0; // largest centre distance of neighbouring surface atoms
  double maxLodgeDepth = 0.0;     // deepest a grain of minGrainRadius sinks between two neighbours
  double worstCornerDeviation = 0.0;  // largest expected corner deviation (cornerDeviation)
  double minInteriorAngle = 0.0;  // sharpest convex corner of the outline [degrees]
  double maxUncoveredInterior = 0.0;  // interior points farther than r + minGrainRadius - margin
                                      // from every atom: the largest such excess (0 = covered)
};
ClumpQuality measureClump(const Shape& shape, const ClumpAtoms& atoms,
                          const ClumpOptions& options = {});

// Places and checks the atoms: throws wiggle::Error when an outline has features too small for the
// atoms (an envelope deviation beyond max(0.1, worst corner deviation)).
ClumpAtoms buildClumpAtoms(const Shape& shape, const ClumpOptions& options = {});


}  // namespace wiggle
