#include "scenario/geometry/Clump.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <optional>
#include <set>
#include <string>

#include "core/Error.h"
#include "core/Format.h"

namespace wiggle {

namespace {
constexpr double kPi = std::numbers::pi;
}  // namespace

double defaultIntruderMass(MassModel model, double density) {
  const double area = kPi * 3.5 * 3.5;  // the disk outline's area [d^2]
  // Mass per area of the grain material: a sphere of diameter d has mass (pi/6) rho d^3 over a
  // disc area (pi/4) d^2, i.e. (2/3) rho d; a disc has rho (per unit thickness d = 1).
  const double perArea = (model == MassModel::Sphere ? 2.0 / 3.0 : 1.0) * density;
  return area * perArea;
}

namespace {

// The two lattices of touching spheres of radius r (pitch 2r) that bodies are built on, each with
// its sites' positions and their touching-or-nearest neighbours counter-clockwise from east:
//   Hexagonal: the glued spheres' densest packing, rows along x sqrt(3) r apart, odd rows shifted by
//     r, a site at the centre (gluedSphereBody: the glued_disk mass rule and the contact mass of a
//     shell); six neighbours.
//   Square: LAMMPS's `lattice sq` of create_atoms, the usual way to fill a region with spheres, its
//     lowest row on the outline's base and a column through the centre (intruder.surface =
//     "lattice"): a slant face cuts it into steps; eight neighbours (the diagonal ones 2 sqrt(2) r
//     apart, a gap no grain passes).
enum class Lattice : std::uint8_t { Hexagonal, Square };

struct LatticeSite {
  int i, j;
  auto operator<=>(const LatticeSite&) const = default;
};

struct LatticeFrame {
  Lattice kind;
  double r;
  double yFirstRow;  // the height of row j = 0

  OutlinePoint position(LatticeSite s) const {
    if (kind == Lattice::Square) return {2.0 * r * s.i, yFirstRow + 2.0 * r * s.j};
    return {2.0 * r * s.i + (s.j % 2 == 0 ? 0.0 : r), yFirstRow + std::sqrt(3.0) * r * s.j};
  }
  double rowPitch() const { return kind == Lattice::Square ? 2.0 * r : std::sqrt(3.0) * r; }
  std::vector<LatticeSite> neighbours(LatticeSite s) const {
    if (kind == Lattice::Square)
      return {{s.i + 1, s.j}, {s.i + 1, s.j + 1}, {s.i, s.j + 1}, {s.i - 1, s.j + 1},
              {s.i - 1, s.j}, {s.i - 1, s.j - 1}, {s.i, s.j - 1}, {s.i + 1, s.j - 1}};
    const int left = s.j % 2 == 0 ? s.i - 1 : s.i;  // the adjacent rows' site just left of this one
    return {{s.i + 1, s.j}, {left + 1, s.j + 1}, {left, s.j + 1}, {s.i - 1, s.j}, {left, s.j - 1}, {left + 1, s.j - 1}};
  }
};

LatticeFrame frameFor(Lattice kind, const Shape& shape, double r) {
  return {kind, r, kind == Lattice::Square ? boundingBox(shape.outline).yMin + r : 0.0};
}

// The sites whose sphere lies inside the outline, row by row.
std::vector<LatticeSite> bodySites(const Shape& shape, const LatticeFrame& frame) {
  const auto depth = depthFunction(shape);
  const OutlineBox box = boundingBox(shape.outline);
  const double pitch = 2.0 * frame.r, rows = frame.rowPitch();
  std::vector<LatticeSite> sites;
  for (int j = static_cast<int>(std::floor((box.yMin - frame.yFirstRow) / rows));
       j <= static_cast<int>(std::ceil((box.yMax - frame.yFirstRow) / rows)); ++j)
    for (int i = static_cast<int>(std::floor(box.xMin / pitch)) - 1; i <= static_cast<int>(std::ceil(box.xMax / pitch)); ++i)
      if (depth(frame.position({i, j})) >= frame.r - 1e-12) sites.push_back({i, j});
  return sites;
}

// The body's outer boundary in order (Moore-neighbour tracing): from the lowest row's leftmost site,
// each next site is the first body site met turning clockwise from the last empty neighbour looked
// at, until the walk comes back to its first step. Consecutive sites are neighbours. A site met
// twice (a neck one sphere wide) is listed once.
std::vector<LatticeSite> traceBoundary(const std::set<LatticeSite>& body, const LatticeFrame& frame) {
  const LatticeSite start = *std::min_element(body.begin(), body.end(), [](LatticeSite a, LatticeSite b) {
    return a.j != b.j ? a.j < b.j : a.i < b.i;
  });
  std::vector<LatticeSite> order{start};
  std::set<LatticeSite> listed{start};
  LatticeSite current = start;
  const int count = static_cast<int>(frame.neighbours(start).size());
  int empty = count / 2;  // the direction of an empty neighbour of `current`: west of the start is empty
  std::optional<LatticeSite> firstStep;
  for (std::size_t step = 0; step < static_cast<std::size_t>(2 * count) * (body.size() + 1); ++step) {
    const std::vector<LatticeSite> n = frame.neighbours(current);
    int k = empty;  // turn clockwise past the empty neighbours
    for (int m = 0; m < count && !body.count(n[(k + count - 1) % count]); ++m) k = (k + count - 1) % count;
    const LatticeSite next = n[(k + count - 1) % count];
    if (!body.count(next)) break;  // a lone sphere: no neighbour at all
    if (current == start && firstStep && next == *firstStep) break;  // back at the first step
    if (!firstStep) firstStep = next;
    const std::vector<LatticeSite> m = frame.neighbours(next);
    empty = static_cast<int>(std::find(m.begin(), m.end(), n[k]) - m.begin());
    current = next;
    if (listed.insert(current).second) order.push_back(current);
  }
  return order;
}

// The shape as it is before intruder.angle turns it: bodies are built upright.
Shape uprightShape(const IntruderDef& def) {
  const Outline vertices(def.vertices.begin(), def.vertices.end());
  return makeShape(def.shape, vertices, 0.0);
}

}  // namespace

std::vector<OutlinePoint> gluedSphereBody(const Shape& shape, double atomRadius) {
  const LatticeFrame frame = frameFor(Lattice::Hexagonal, shape, atomRadius);
  std::vector<OutlinePoint> centres;
  for (const LatticeSite& site : bodySites(shape, frame)) centres.push_back(frame.position(site));
  return centres;
}

namespace {

// intruder.surface = "lattice": the upright outline filled with the square lattice's spheres,
// turned with the outline; its outer boundary, in order, is the shell, the rest guards.
ClumpAtoms latticeClumpAtoms(const IntruderDef& def, double atomRadius) {
  const Shape upright = uprightShape(def);
  const LatticeFrame frame = frameFor(Lattice::Square, upright, atomRadius);
  const std::vector<LatticeSite> sites = bodySites(upright, frame);
  if (sites.empty())
    throw Error("intruder '" + std::string(choiceName(def.shape)) + "': no sphere of radius " + formatNumber(atomRadius) +
                " d fits inside the outline (intruder.surface = lattice)");
  const std::set<LatticeSite> body(sites.begin(), sites.end());
  const std::vector<LatticeSite> boundary = traceBoundary(body, frame);
  const std::set<LatticeSite> onBoundary(boundary.begin(), boundary.end());
  Outline shell, interior;
  for (const LatticeSite& site : boundary) shell.push_back(frame.position(site));
  for (const LatticeSite& site : sites)
    if (!onBoundary.count(site)) interior.push_back(frame.position(site));
  // Turned as the outline is (a disk's angle is ignored: makeShape).
  const double angle = upright.isDisk() ? 0.0 : def.angle;
  ClumpAtoms atoms;
  atoms.atomRadius = atomRadius;
  atoms.surface = rotated(std::move(shell), angle);
  atoms.guard = rotated(std::move(interior), angle);
  return atoms;
}

}  // namespace

ClumpAtoms clumpAtomsFor(const IntruderDef& def, const Shape& shape) {
  if (def.surface == IntruderSurface::Lattice) return latticeClumpAtoms(def, ClumpOptions{}.atomRadius);
  return buildClumpAtoms(shape, clumpOptionsFor(def));
}

double gluedDiskMass(MassModel model, double density, double atomRadius) {
  const std::size_t atoms = gluedSphereBody(makeShape(ShapeName::Disk), atomRadius).size();
  const double r = atomRadius;
  const double atomMass = (model == MassModel::Sphere ? 4.0 / 3.0 * kPi * r * r * r : kPi * r * r) * density;
  return static_cast<double>(atoms) * atomMass;
}

namespace {

// The centres of the spheres of the body an intruder is built of, upright: a lattice body's own,
// else the hexagonal body of glued spheres a shell stands for.
std::vector<OutlinePoint> builtOfSpheres(const IntruderDef& def, double r) {
  const Shape upright = uprightShape(def);
  if (def.surface != IntruderSurface::Lattice) return gluedSphereBody(upright, r);
  const LatticeFrame frame = frameFor(Lattice::Square, upright, r);
  std::vector<OutlinePoint> centres;
  for (const LatticeSite& site : bodySites(upright, frame)) centres.push_back(frame.position(site));
  return centres;
}

}  // namespace

std::uint32_t contactMassShares(const IntruderDef& def) {
  if (def.contactMass == ContactMass::Body) return 1;
  return static_cast<std::uint32_t>(builtOfSpheres(def, ClumpOptions{}.atomRadius).size());
}

double bodyInertia(const IntruderDef& def, double mass, MassModel model) {
  const double r = ClumpOptions{}.atomRadius;
  const std::vector<OutlinePoint> spheres = builtOfSpheres(def, r);
  const double own = (model == MassModel::Sphere ? 0.4 : 0.5) * r * r;  // a sphere's about its centre, per mass
  double sum = 0.0;
  for (const OutlinePoint& c : spheres) sum += c[0] * c[0] + c[1] * c[1] + own;
  return mass / static_cast<double>(spheres.size()) * sum;
}

double intruderMass(const IntruderDef& def, MassModel model, double density) {
  if (!std::isfinite(def.mass) || def.mass < 0.0)
    throw Error("intruder.mass: must be positive (or 0 for the mass rule), got " + formatNumber(def.mass));
  if (def.mass > 0.0) return def.mass;
  return def.massRule == MassRule::GluedDisk ? gluedDiskMass(model, density) : defaultIntruderMass(model, density);
}

ClumpDef makeClump(const IntruderDef& def, MassModel model, double density) {
  return makeClump(def, makeShape(def), model, density);
}

ClumpDef makeClump(const IntruderDef& def, const Shape& shape, MassModel model, double density) {
  const ClumpAtoms atoms = clumpAtomsFor(def, shape);
  ClumpDef clump;
  clump.atomRadius = atoms.atomRadius;
  clump.mass = intruderMass(def, model, density);
  clump.massShares = contactMassShares(def);
  if (def.rotation == IntruderRotation::Free) clump.inertia = bodyInertia(def, clump.mass, model);
  for (const auto* list : {&atoms.surface, &atoms.guard})
    for (const OutlinePoint& p : *list) {
      clump.offsetX.push_back(p[0]);
      clump.offsetY.push_back(p[1]);
    }
  return clump;
}

}  // namespace wiggle
