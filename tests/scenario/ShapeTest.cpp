// Intruder shapes and their atom clumps: outline dimensions from the paper's table, the two-sided
// envelope tolerance (checked here with the test's own geometry, not measureClump's), the no-lodge
// argument, interior coverage, polygon validation and the mass rule.
#include "scenario/geometry/Clump.h"
#include "scenario/geometry/Shape.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>

#include "core/Error.h"

namespace wiggle {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kR = 0.25;  // atom radius

struct Extents {
  double xMin, xMax, yMin, yMax;
  double width() const { return xMax - xMin; }
  double height() const { return yMax - yMin; }
};

// Extents over the atoms' outer edges.
Extents atomExtents(const ClumpDef& c) {
  Extents e{1e9, -1e9, 1e9, -1e9};
  for (std::size_t i = 0; i < c.offsetX.size(); ++i) {
    e.xMin = std::min(e.xMin, c.offsetX[i] - c.atomRadius);
    e.xMax = std::max(e.xMax, c.offsetX[i] + c.atomRadius);
    e.yMin = std::min(e.yMin, c.offsetY[i] - c.atomRadius);
    e.yMax = std::max(e.yMax, c.offsetY[i] + c.atomRadius);
  }
  return e;
}

ClumpDef clumpFor(ShapeName shape, double angle = 0.0) {
  IntruderDef def;
  def.shape = shape;
  def.angle = angle;
  return makeClump(def, MassModel::Sphere, 1.0);
}

// The test's own point-to-outline geometry (independent of scenario/geometry/Polygon.cpp).
double segDist(OutlinePoint a, OutlinePoint b, OutlinePoint p) {
  const double ex = b[0] - a[0], ey = b[1] - a[1];
  double t = ((p[0] - a[0]) * ex + (p[1] - a[1]) * ey) / (ex * ex + ey * ey);
  t = std::max(0.0, std::min(1.0, t));
  return std::hypot(p[0] - a[0] - t * ex, p[1] - a[1] - t * ey);
}
bool inside(const Outline& poly, OutlinePoint p) {  // winding number
  int wn = 0;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const OutlinePoint a = poly[i], b = poly[(i + 1) % poly.size()];
    const double c = (b[0] - a[0]) * (p[1] - a[1]) - (p[0] - a[0]) * (b[1] - a[1]);
    if (a[1] <= p[1] && b[1] > p[1] && c > 0) ++wn;
    if (a[1] > p[1] && b[1] <= p[1] && c < 0) --wn;
  }
  return wn != 0;
}
double signedDepth(const Outline& poly, OutlinePoint p) {
  double d = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < poly.size(); ++i)
    d = std::min(d, segDist(poly[i], poly[(i + 1) % poly.size()], p));
  return inside(poly, p) ? d : -d;
}

// Two-sided envelope deviation: (a) how far any atom's disc reaches beyond the outline;
// (b) how far any outline point is from the nearest atom's disc.
struct Envelope {
  double overshoot = -1e9, gap = 0.0;
};
Envelope envelope(const Outline& poly, const ClumpDef& c) {
  Envelope e;
  for (std::size_t i = 0; i < c.offsetX.size(); ++i)
    for (int k = 0; k < 72; ++k) {  // every 5 deg: misses the extreme by r(1 - cos 2.5) < 3e-4
      const double a = 2 * kPi * k / 72;
      const OutlinePoint p{c.offsetX[i] + kR * std::cos(a), c.offsetY[i] + kR * std::sin(a)};
      e.overshoot = std::max(e.overshoot, -signedDepth(poly, p));
    }
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const OutlinePoint a = poly[i], b = poly[(i + 1) % poly.size()];
    const int m = std::max(1, static_cast<int>(std::hypot(b[0] - a[0], b[1] - a[1]) / 0.004));
    for (int k = 0; k < m; ++k) {
      const OutlinePoint p{a[0] + (b[0] - a[0]) * k / m, a[1] + (b[1] - a[1]) * k / m};
      double best = 1e9;
      for (std::size_t j = 0; j < c.offsetX.size(); ++j)
        best = std::min(best, std::hypot(p[0] - c.offsetX[j], p[1] - c.offsetY[j]) - kR);
      e.gap = std::max(e.gap, best);
    }
  }
  return e;
}

TEST(Shape, PaperOutlinesHaveTheTableDimensions) {
  struct Row {
    ShapeName kind;
    double w, h;
  };
  const double triH = 9.5 * std::sqrt(3.0) / 2.0;
  for (const Row& r : {Row{ShapeName::Disk, 7.0, 7.0}, Row{ShapeName::Square, 6.5, 6.5}, Row{ShapeName::RectNarrow, 4.5, 9.5},
                       Row{ShapeName::RectWide, 9.5, 4.5}, Row{ShapeName::Triangle, 9.5, triH}}) {
    const Shape s = makeShape(r.kind);
    const OutlineBox box = boundingBox(s.outline);
    EXPECT_NEAR(box.width(), r.w, 1e-12) << choiceName(r.kind);
    EXPECT_NEAR(box.height(), r.h, 1e-12) << choiceName(r.kind);
    const OutlinePoint c = areaCentroid(s.outline);  // the clump centre is the centroid
    EXPECT_NEAR(c[0], 0.0, 1e-9) << choiceName(r.kind);
    EXPECT_NEAR(c[1], 0.0, 1e-9) << choiceName(r.kind);
  }
  // Triangle: base H/3 below the centre, apex 2H/3 above; all sides 9.5.
  const Outline tri = makeShape(ShapeName::Triangle).outline;
  EXPECT_NEAR(boundingBox(tri).yMin, -triH / 3.0, 1e-12);
  for (std::size_t i = 0; i < 3; ++i)
    EXPECT_NEAR(std::hypot(tri[(i + 1) % 3][0] - tri[i][0], tri[(i + 1) % 3][1] - tri[i][1]), 9.5,
                1e-12);
  EXPECT_NEAR(std::abs(signedArea(makeShape(ShapeName::Disk).outline)), kPi * 3.5 * 3.5, 2e-3);
}

TEST(Shape, ClumpExtentsMatchTheTable) {
  struct Row {
    ShapeName kind;
    double w, h;
  };
  const double triH = 9.5 * std::sqrt(3.0) / 2.0;
  for (const Row& r : {Row{ShapeName::Disk, 7.0, 7.0}, Row{ShapeName::Square, 6.5, 6.5}, Row{ShapeName::RectNarrow, 4.5, 9.5},
                       Row{ShapeName::RectWide, 9.5, 4.5}, Row{ShapeName::Triangle, 9.5, triH}}) {
    const Extents e = atomExtents(clumpFor(r.kind));
    EXPECT_NEAR(e.width(), r.w, 0.1) << choiceName(r.kind);
    EXPECT_NEAR(e.height(), r.h, 0.1) << choiceName(r.kind);
  }
  // The disk's ring is exact: atoms on radius 3.25 at 0, 90, 180, 270 deg among others.
  const Extents d = atomExtents(clumpFor(ShapeName::Disk));
  EXPECT_NEAR(d.width(), 7.0, 1e-12);
  EXPECT_NEAR(d.yMax, 3.5, 1e-12);
}

TEST(Shape, EnvelopeWithinToleranceBothWays) {
  for (const ShapeName kind : namedShapes()) {
    const std::string_view name = choiceName(kind);
    const Shape s = makeShape(kind);
    const Envelope e = envelope(s.outline, clumpFor(kind));
    EXPECT_LE(e.overshoot, 0.1) << name;
    EXPECT_LE(e.gap, 0.1) << name;
    // measureClump agrees with this independent evaluation.
    const ClumpQuality q = measureClump(s, buildClumpAtoms(s));
    EXPECT_NEAR(q.maxOutlineGap, e.gap, 0.003) << name;
    EXPECT_NEAR(std::max(0.0, q.maxOvershoot), std::max(0.0, e.overshoot), 0.003) << name;
    EXPECT_LE(q.maxEnvelopeDepth, 0.1) << name;
  }
  // The numbers documented in docs/SHAPES.md: the square's corner gap is the 0.09 budget and its
  // corner atoms poke out by r - 0.34 sin 45 deg; the triangle's 60 deg corners by r - 0.34 sin 30.
  const Envelope sq = envelope(makeShape(ShapeName::Square).outline, clumpFor(ShapeName::Square));
  EXPECT_NEAR(sq.gap, 0.09, 0.002);
  EXPECT_NEAR(sq.overshoot, kR - 0.34 * std::sin(kPi / 4), 0.001);
  const Envelope tri = envelope(makeShape(ShapeName::Triangle).outline, clumpFor(ShapeName::Triangle));
  EXPECT_NEAR(tri.overshoot, kR - 0.34 * 0.5, 0.001);
}

TEST(Shape, CornerDeviationRule) {
  const ClumpOptions o;
  EXPECT_NEAR(cornerDeviation(kPi / 2, o), 0.09, 1e-12);  // gap budget, small overshoot
  EXPECT_NEAR(cornerDeviation(kPi / 3, o), 0.09, 1e-12);  // 60 deg: overshoot 0.08 < gap 0.09
  EXPECT_NEAR(cornerDeviation(2 * kPi / 3, o), kR / std::sin(kPi / 3) - kR, 1e-12);  // natural
  // The sharpest corner that the 0.1 tolerance allows: sin(theta/2) = (r - 0.1)/(r + 0.1).
  const double limit = 2 * std::asin(0.15 / 0.35);
  EXPECT_NEAR(limit * 180 / kPi, 50.76, 0.01);
  EXPECT_NEAR(cornerDeviation(limit, o), 0.1, 1e-12);
  EXPECT_GT(cornerDeviation(limit - 0.01, o), 0.1);
}

TEST(Shape, NoGrainLodgesBetweenSurfaceAtoms) {
  // A grain of the smallest diameter 0.9 (radius 0.45) pressed onto two neighbouring atoms a
  // distance s apart touches both with its centre on their bisector, sqrt(0.7^2 - (s/2)^2) from
  // their centre line: it sinks 0.7 - sqrt(0.49 - s^2/4) below their common tangent. Neighbours
  // must overlap (s < 0.5, so the shell has no opening at all) and the dimple must be shallow.
  double worst = 0.0, widest = 0.0;
  for (const ShapeName kind : namedShapes()) {
    const std::string_view name = choiceName(kind);
    const ClumpAtoms atoms = buildClumpAtoms(makeShape(kind));
    const auto& a = atoms.surface;
    for (std::size_t i = 0; i < a.size(); ++i) {
      const auto& p = a[i];
      const auto& q = a[(i + 1) % a.size()];
      const double s = std::hypot(q[0] - p[0], q[1] - p[1]);
      widest = std::max(widest, s);
      ASSERT_LT(s, 2 * kR) << name << ": gap between surface atoms " << i;
      worst = std::max(worst, 0.7 - std::sqrt(0.49 - 0.25 * s * s));
    }
  }
  EXPECT_LE(widest, 0.35 + 1e-9);
  EXPECT_LT(worst, 0.025);  // about 1/36 of the grain's diameter: no pocket to sit in
  // Touching atoms (s = 0.5) would give 0.046 and a grain-sized spacing would let grains through.
  EXPECT_GT(0.7 - std::sqrt(0.49 - 0.0625), 0.045);
}

TEST(Shape, NoGrainFitsInsideTheOutline) {
  // Any grain (radius >= 0.45) centred inside the outline overlaps some atom, so a bed maker that
  // checks overlaps with atoms can never leave a grain inside the (mostly hollow) clump.
  std::mt19937_64 rng(7);
  for (const ShapeName kind : namedShapes()) {
    const std::string_view name = choiceName(kind);
    const Shape s = makeShape(kind);
    const ClumpDef c = clumpFor(kind);
    const OutlineBox box = boundingBox(s.outline);
    std::uniform_real_distribution<double> ux(box.xMin, box.xMax), uy(box.yMin, box.yMax);
    int tested = 0;
    for (int k = 0; k < 20000; ++k) {
      const OutlinePoint p{ux(rng), uy(rng)};
      if (!inside(s.outline, p)) continue;
      ++tested;
      double best = 1e9;
      for (std::size_t j = 0; j < c.offsetX.size(); ++j)
        best = std::min(best, std::hypot(p[0] - c.offsetX[j], p[1] - c.offsetY[j]));
      ASSERT_LT(best, kR + 0.45) << name << " at (" << p[0] << ", " << p[1] << ")";
    }
    EXPECT_GT(tested, 5000) << name;
  }
}

TEST(Shape, RotatingNarrowRectangleBy90GivesWideExtents) {
  const Extents rotated = atomExtents(clumpFor(ShapeName::RectNarrow, 90.0));
  const Extents wide = atomExtents(clumpFor(ShapeName::RectWide));
  EXPECT_NEAR(rotated.width(), wide.width(), 1e-9);
  EXPECT_NEAR(rotated.height(), wide.height(), 1e-9);
  const OutlineBox box = boundingBox(makeShape(ShapeName::RectNarrow, {}, 90.0).outline);
  EXPECT_NEAR(box.width(), 9.5, 1e-12);
  EXPECT_NEAR(box.height(), 4.5, 1e-12);
  // A general angle: rotating the outline by 30 deg keeps the area and turns a vertex as expected.
  const Outline r30 = makeShape(ShapeName::RectWide, {}, 30.0).outline;
  EXPECT_NEAR(signedArea(r30), 9.5 * 4.5, 1e-9);
  const double c = std::cos(kPi / 6), s = std::sin(kPi / 6);
  EXPECT_NEAR(r30[1][0], c * 4.75 - s * -2.25, 1e-12);
  EXPECT_NEAR(r30[1][1], s * 4.75 + c * -2.25, 1e-12);
}

TEST(Shape, ConcaveLShape) {
  // An L: 4 x 1 foot and a 1 x 4 upright, given clockwise and off-centre.
  Outline l = {{10, 10}, {10, 14}, {11, 14}, {11, 11}, {14, 11}, {14, 10}};
  IntruderDef def;
  def.shape = ShapeName::Polygon;
  for (const auto& p : l) def.vertices.push_back(p);
  const Shape s = makeShape(def);
  EXPECT_GT(signedArea(s.outline), 0.0);  // made counter-clockwise
  EXPECT_NEAR(signedArea(s.outline), 7.0, 1e-12);
  const OutlinePoint c = areaCentroid(s.outline);
  EXPECT_NEAR(c[0], 0.0, 1e-12);
  EXPECT_NEAR(c[1], 0.0, 1e-12);
  const ClumpDef clump = makeClump(def, MassModel::Disc, 1.0);
  const Envelope e = envelope(s.outline, clump);
  EXPECT_LE(e.overshoot, 0.1);
  EXPECT_LE(e.gap, 0.1);
  // The reflex (inner) corner is at (11, 11) before centring: an atom touches it.
  // Centroid of the L before centring: foot (4 x 1) at (12, 10.5), upright (1 x 3) at (10.5, 12.5).
  const double cx = (4 * 12.0 + 3 * 10.5) / 7.0, cy = (4 * 10.5 + 3 * 12.5) / 7.0;
  double best = 1e9;
  for (std::size_t j = 0; j < clump.offsetX.size(); ++j)
    best = std::min(best, std::hypot(11 - cx - clump.offsetX[j], 11 - cy - clump.offsetY[j]) - kR);
  EXPECT_NEAR(best, 0.0, 1e-9);
  EXPECT_DOUBLE_EQ(clump.mass, kPi * 3.5 * 3.5);
}

TEST(Shape, RejectsBadPolygons) {
  auto message = [](const Outline& v) {
    try {
      makeShape(ShapeName::Polygon, v);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(message({{0, 0}, {2, 2}, {2, 0}, {0, 2}}).find("self-intersecting"), std::string::npos);
  EXPECT_NE(message({{0, 0}, {1, 0}}).find("at least 3 vertices"), std::string::npos);
  EXPECT_NE(message({{0, 0}, {1, 0}, {1, 0}, {0, 1}}).find("repeated"), std::string::npos);
  EXPECT_NE(message({{0, 0}, {1, 1}, {2, 2}}).find("zero area"), std::string::npos);
  EXPECT_NE(message({{0, 0}, {1, NAN}, {0, 1}}).find("finite"), std::string::npos);
  EXPECT_NE(message({{0, 0}, {4, 0}, {4, 4}, {2, 0}, {0, 4}}).find("self-intersecting"),
            std::string::npos);  // touches its own edge at (2, 0)
  EXPECT_EQ(message({}), "intruder.vertices: shape 'polygon' needs a vertex list");
  EXPECT_EQ(message({{0, 0}, {4, 0}, {4, 4}, {0, 4}}), "accepted");
  EXPECT_EQ(message({{0, 0}, {0, 4}, {4, 4}, {4, 0}}), "accepted");  // clockwise is fine
  EXPECT_THROW(makeShape(ShapeName::Square, {{0, 0}, {1, 0}, {0, 1}}), Error);
  EXPECT_THROW(makeShape(ShapeName::Square, {}, NAN), Error);
  // The self-intersection check works on any vertex list.
  EXPECT_TRUE(findSelfIntersection({{0, 0}, {2, 2}, {2, 0}, {0, 2}}).has_value());
  EXPECT_FALSE(findSelfIntersection({{0, 0}, {2, 0}, {2, 2}, {1, 1}, {0, 2}}).has_value());
}

TEST(Shape, RejectsFeaturesTooSmallForAtoms) {
  // A sliver 0.2 wide cannot hold atoms of diameter 0.5 within 0.1.
  IntruderDef def;
  def.shape = ShapeName::Polygon;
  def.vertices = {{0, 0}, {5, 0}, {5, 0.2}, {0, 0.2}};
  EXPECT_THROW(makeClump(def, MassModel::Sphere, 1.0), Error);
  // A 30 deg spike: accepted, with the corner's own (larger) deviation.
  def.vertices = {{0, 0}, {6, 0}, {6 * std::cos(kPi / 6), 6 * std::sin(kPi / 6)}};
  const ClumpDef c = makeClump(def, MassModel::Sphere, 1.0);
  const Envelope e = envelope(makeShape(def).outline, c);
  const double expected = cornerDeviation(kPi / 6);
  EXPECT_GT(expected, 0.1);
  EXPECT_LE(e.gap, expected + 1e-3);
  EXPECT_LE(e.overshoot, expected + 1e-3);
}

TEST(Shape, MassRule) {
  EXPECT_NEAR(defaultIntruderMass(MassModel::Sphere, 1.0), 25.66, 0.005);
  EXPECT_NEAR(defaultIntruderMass(MassModel::Disc, 1.0), 38.48, 0.005);
  EXPECT_DOUBLE_EQ(defaultIntruderMass(MassModel::Disc, 2.0), 2 * kPi * 12.25);
  // Sphere rule = a unit grain's sphere mass over its disc area, times the disk's area.
  EXPECT_NEAR(defaultIntruderMass(MassModel::Sphere, 1.0),
              kPi * 12.25 * particleMass(MassModel::Sphere, 1.0, 0.5) / (kPi * 0.25), 1e-12);
  IntruderDef def;
  def.shape = ShapeName::Triangle;
  EXPECT_NEAR(makeClump(def, MassModel::Sphere, 1.0).mass, 25.656, 0.001);  // same for every shape
  def.mass = 12.5;
  EXPECT_DOUBLE_EQ(makeClump(def, MassModel::Sphere, 1.0).mass, 12.5);
  def.mass = -1.0;
  EXPECT_THROW(makeClump(def, MassModel::Sphere, 1.0), Error);
}

TEST(Shape, GluedDiskMassIsAHexagonalPackingOfTouchingSpheres) {
  // Atoms of radius 0.25 whose centres lie within 3.25 of the centre, on a hexagonal lattice of
  // pitch 0.5: about pi/(2 sqrt 3) x (3.25 / 0.25)^2 = 153.3 of them (the lattice's packing fraction
  // times the inner disk's area over an atom's); each a sphere of (4/3) pi 0.25^3.
  const double atom = 4.0 / 3.0 * kPi * 0.25 * 0.25 * 0.25;
  const double atoms = gluedDiskMass(MassModel::Sphere, 1.0) / atom;
  EXPECT_NEAR(atoms, std::round(atoms), 1e-9);  // a whole number of atoms
  EXPECT_NEAR(atoms, 153.3, 6.0);  // 151: the boundary loses a few
  EXPECT_NEAR(gluedDiskMass(MassModel::Disc, 1.0) / (kPi * 0.0625), atoms, 1e-9);  // the same atoms as discs
  EXPECT_NEAR(gluedDiskMass(MassModel::Sphere, 2.0), 2.0 * gluedDiskMass(MassModel::Sphere, 1.0), 1e-12);
  // The rule gives it to every shape, and an explicit mass still wins.
  IntruderDef def;
  def.shape = ShapeName::Triangle;
  def.massRule = MassRule::GluedDisk;
  EXPECT_DOUBLE_EQ(makeClump(def, MassModel::Sphere, 1.0).mass, gluedDiskMass(MassModel::Sphere, 1.0));
  def.mass = 12.5;
  EXPECT_DOUBLE_EQ(makeClump(def, MassModel::Sphere, 1.0).mass, 12.5);
}

// The body of glued spheres (gluedSphereBody): every sphere inside the outline, touching neighbours on
// a hexagonal lattice, and about as many as the lattice's packing fraction fills of the outline
// shrunk by r (the area the centres can reach), less what its boundary cuts. Its count is the
// number of shares of intruder.contact_mass = "atom", the same at any angle.
TEST(Shape, GluedSphereBodyFillsEachOutlineWithTouchingSpheres) {
  const double r = 0.25;
  for (const ShapeName kind : namedShapes()) {
    const Shape shape = makeShape(kind);
    const std::vector<OutlinePoint> body = gluedSphereBody(shape, r);
    const auto depth = [&](OutlinePoint p) {
      return shape.isDisk() ? shape.diskRadius - std::hypot(p[0], p[1]) : depthInside(shape.outline, p);
    };
    double closest = 1e300;
    for (std::size_t a = 0; a < body.size(); ++a) {
      EXPECT_GE(depth(body[a]), r - 1e-12) << choiceName(kind);
      for (std::size_t b = a + 1; b < body.size(); ++b)
        closest = std::min(closest, std::hypot(body[a][0] - body[b][0], body[a][1] - body[b][1]));
    }
    EXPECT_NEAR(closest, 2 * r, 1e-12) << choiceName(kind);  // touching, never overlapping
    // The reachable area (the outline shrunk by r) over a lattice cell's 2 sqrt(3) r^2; the boundary
    // adds or loses up to a site per 2r of perimeter (a lattice line on an edge keeps all its sites).
    const Outline& o = shape.outline;
    double perimeter = 0.0;
    for (std::size_t i = 0; i < o.size(); ++i)
      perimeter += std::hypot(o[(i + 1) % o.size()][0] - o[i][0], o[(i + 1) % o.size()][1] - o[i][1]);
    const double area = signedArea(o);
    const double reachable = area - perimeter * r + kPi * r * r;  // a convex outline's inner parallel set
    const double expected = reachable / (2 * std::sqrt(3.0) * r * r);
    EXPECT_NEAR(static_cast<double>(body.size()), expected, perimeter / (2 * r)) << choiceName(kind);
  }
  EXPECT_EQ(gluedSphereBody(makeShape(ShapeName::Disk), r).size(), 151u);  // docs/SHAPES.md, "Mass"

  IntruderDef def;
  def.shape = ShapeName::Triangle;
  EXPECT_EQ(contactMassShares(def), 1u);  // "body": the whole mass
  EXPECT_EQ(makeClump(def, MassModel::Sphere, 1.0).massShares, 1u);
  def.contactMass = ContactMass::Atom;
  const std::uint32_t upright = contactMassShares(def);
  EXPECT_EQ(upright, gluedSphereBody(makeShape(ShapeName::Triangle), r).size());
  def.angle = 180.0;  // the body is built upright, then turned
  EXPECT_EQ(contactMassShares(def), upright);
  const ClumpDef clump = makeClump(def, MassModel::Sphere, 1.0);
  EXPECT_EQ(clump.massShares, upright);
  EXPECT_DOUBLE_EQ(clump.contactMass(), clump.mass / upright);
}

// intruder.surface = "lattice": the upright outline filled with touching spheres on a square lattice
// whose lowest row rests on the base, turned with the outline; its shell traced in order around it.
// The paper's shapes: each has a base for that row to rest on, which another outline may not.
TEST(Shape, LatticeBodyFillsTheUprightOutlineAndTurnsWithIt) {
  const double r = 0.25;
  for (const ShapeName kind : paperShapes()) {
    IntruderDef def;
    def.shape = kind;
    def.surface = IntruderSurface::Lattice;
    const Shape shape = makeShape(def);
    const ClumpAtoms atoms = clumpAtomsFor(def, shape);
    std::vector<OutlinePoint> all = atoms.surface;
    all.insert(all.end(), atoms.guard.begin(), atoms.guard.end());
    double lowest = 1e300, closest = 1e300;
    for (std::size_t a = 0; a < all.size(); ++a) {
      const double depth = shape.isDisk() ? shape.diskRadius - std::hypot(all[a][0], all[a][1])
                                          : depthInside(shape.outline, all[a]);
      EXPECT_GE(depth, r - 1e-12) << choiceName(kind);  // wholly inside
      lowest = std::min(lowest, all[a][1]);
      for (std::size_t b = a + 1; b < all.size(); ++b) closest = std::min(closest, std::hypot(all[a][0] - all[b][0], all[a][1] - all[b][1]));
      // on the square lattice of pitch 2r with a column through the centre
      EXPECT_NEAR(std::remainder(all[a][0], 2 * r), 0.0, 1e-9) << choiceName(kind);
    }
    EXPECT_NEAR(closest, 2 * r, 1e-12) << choiceName(kind);  // touching
    EXPECT_NEAR(lowest, boundingBox(shape.outline).yMin + r, 1e-12) << choiceName(kind);  // resting on the base
    // The shell in order: consecutive boundary spheres are lattice neighbours (touching or diagonal).
    for (std::size_t a = 0; a < atoms.surface.size(); ++a) {
      const OutlinePoint p = atoms.surface[a], q = atoms.surface[(a + 1) % atoms.surface.size()];
      EXPECT_LE(std::hypot(p[0] - q[0], p[1] - q[1]), 2 * std::sqrt(2.0) * r + 1e-9) << choiceName(kind) << " " << a;
    }
    // Its spheres share the mass in contacts with intruder.contact_mass = "atom".
    def.contactMass = ContactMass::Atom;
    EXPECT_EQ(contactMassShares(def), all.size()) << choiceName(kind);
    EXPECT_EQ(makeClump(def, MassModel::Sphere, 1.0).offsetX.size(), all.size());
  }
  // The square and the rectangles hold whole rows and columns: their outline within the glued
  // shell's 0.104 of the atoms; the triangle's slant faces cut the rows into steps.
  IntruderDef def;
  def.surface = IntruderSurface::Lattice;
  for (const ShapeName kind : {ShapeName::Square, ShapeName::RectNarrow, ShapeName::RectWide}) {
    def.shape = kind;
    const Shape shape = makeShape(def);
    EXPECT_LT(measureClump(shape, clumpAtomsFor(def, shape)).maxOutlineGap, 0.105) << choiceName(kind);
  }
  def.shape = ShapeName::Triangle;
  const Shape triangle = makeShape(def);
  EXPECT_GT(measureClump(triangle, clumpAtomsFor(def, triangle)).maxOutlineGap, 0.5);
  // Apex down: the upright body turned by 180 degrees, sphere for sphere.
  IntruderDef down = def;
  down.angle = 180.0;
  const ClumpAtoms up = clumpAtomsFor(def, triangle), turned = clumpAtomsFor(down, makeShape(down));
  ASSERT_EQ(turned.surface.size(), up.surface.size());
  ASSERT_EQ(turned.guard.size(), up.guard.size());
  for (std::size_t a = 0; a < up.guard.size(); ++a) {
    EXPECT_NEAR(turned.guard[a][0], -up.guard[a][0], 1e-12);
    EXPECT_NEAR(turned.guard[a][1], -up.guard[a][1], 1e-12);
  }
  // An outline no sphere fits in is refused, naming the surface.
  IntruderDef sliver;
  sliver.shape = ShapeName::Polygon;
  sliver.vertices = {{0.0, 0.0}, {3.0, 0.0}, {0.0, 0.3}};
  sliver.surface = IntruderSurface::Lattice;
  try {
    clumpAtomsFor(sliver, makeShape(sliver));
    FAIL() << "a sliver 0.3 d tall was given a lattice body";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("intruder.surface = lattice"), std::string::npos) << e.what();
  }
}

TEST(Shape, GluedSurfaceHasTouchingAtomsAndStillHoldsGrainsOut) {
  // intruder.surface = "glued": neighbouring surface atoms touch (spacing up to 2r = 0.5, against
  // 0.35 for the smooth surface), so the envelope has cusps 0.25 deep, but no grain of radius
  // >= 0.45 can pass between two atoms nor sit inside the outline.
  std::mt19937_64 rng(11);
  for (const ShapeName kind : namedShapes()) {
    const std::string_view name = choiceName(kind);
    IntruderDef def;
    def.shape = kind;
    def.surface = IntruderSurface::Glued;
    const Shape shape = makeShape(def);
    const ClumpAtoms atoms = buildClumpAtoms(shape, clumpOptionsFor(def));
    const ClumpQuality q = measureClump(shape, atoms, clumpOptionsFor(def));
    EXPECT_LE(q.maxSurfaceSpacing, 0.5 + 1e-9) << name;
    EXPECT_GT(q.maxSurfaceSpacing, 0.4) << name;
    EXPECT_LT(q.maxLodgeDepth, 0.05) << name;  // 0.7 - sqrt(0.49 - 0.0625) = 0.046 at the widest gap
    const ClumpAtoms smooth = buildClumpAtoms(shape);
    EXPECT_LT(atoms.surface.size(), smooth.surface.size()) << name;
    const ClumpDef c = makeClump(def, MassModel::Sphere, 1.0);
    const OutlineBox box = boundingBox(shape.outline);
    std::uniform_real_distribution<double> ux(box.xMin, box.xMax), uy(box.yMin, box.yMax);
    for (int k = 0; k < 5000; ++k) {
      const OutlinePoint p{ux(rng), uy(rng)};
      if (!inside(shape.outline, p)) continue;
      double best = 1e9;
      for (std::size_t j = 0; j < c.offsetX.size(); ++j)
        best = std::min(best, std::hypot(p[0] - c.offsetX[j], p[1] - c.offsetY[j]));
      ASSERT_LT(best, kR + 0.45) << name << " at (" << p[0] << ", " << p[1] << ")";
    }
  }
}

TEST(Shape, ClumpIsCentredAndSymmetric) {
  // Mirror-symmetric shapes (the paper's five are) give mirror-symmetric clumps about x = 0, so the
  // clump's atoms have no net horizontal offset; atom count stays small.
  for (const ShapeName kind : paperShapes()) {
    const std::string_view name = choiceName(kind);
    const ClumpDef c = clumpFor(kind);
    double sx = 0.0;
    for (double x : c.offsetX) sx += x;
    EXPECT_NEAR(sx / c.offsetX.size(), 0.0, 0.02) << name;
    EXPECT_LT(c.offsetX.size(), 140u) << name;
    EXPECT_DOUBLE_EQ(c.atomRadius, 0.25);
  }
}

}  // namespace
}  // namespace wiggle
