#include "scenario/geometry/Shape.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <limits>
#include <numbers>
#include <optional>
#include <set>
#include <string>
#include <unordered_map>

#include "core/Error.h"

namespace wiggle {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDiskDiameter = 7.0;    // OS1 [d]
constexpr int kDiskOutlineVertices = 720;  // a multiple of 4: vertices at the poles and equator

struct V2 {
  double x = 0.0, y = 0.0;
};
V2 operator+(V2 a, V2 b) { return {a.x + b.x, a.y + b.y}; }
V2 operator-(V2 a, V2 b) { return {a.x - b.x, a.y - b.y}; }
V2 operator*(double s, V2 a) { return {s * a.x, s * a.y}; }
double dot(V2 a, V2 b) { return a.x * b.x + a.y * b.y; }
double crossZ(V2 a, V2 b) { return a.x * b.y - a.y * b.x; }
double norm(V2 a) { return std::hypot(a.x, a.y); }
V2 unit(V2 a) {
  const double n = norm(a);
  return {a.x / n, a.y / n};
}
V2 toV2(const OutlinePoint& p) { return {p[0], p[1]}; }
OutlinePoint toPoint(V2 v) { return {v.x, v.y}; }

Outline rectangle(double width, double height) {
  const double hx = 0.5 * width, hy = 0.5 * height;
  return {{-hx, -hy}, {hx, -hy}, {hx, hy}, {-hx, hy}};
}

Outline diskOutline(double radius) {
  Outline out;
  out.reserve(kDiskOutlineVertices);
  for (int k = 0; k < kDiskOutlineVertices; ++k) {
    // Quarter points set exactly, so top = +R, equator at y = 0 and extents 2R hold bit for bit.
    double c, s;
    if (k % (kDiskOutlineVertices / 4) == 0) {
      const int q = k / (kDiskOutlineVertices / 4);
      c = (q == 0) ? 1.0 : (q == 2 ? -1.0 : 0.0);
      s = (q == 1) ? 1.0 : (q == 3 ? -1.0 : 0.0);
    } else {
      const double a = 2.0 * kPi * k / kDiskOutlineVertices;
      c = std::cos(a);
      s = std::sin(a);
    }
    out.push_back({radius * c, radius * s});
  }
  return out;
}

// Equilateral triangle of side a, apex up, flat base down, centroid at the origin: the base is
// H/3 below the centroid and the apex 2H/3 above it (H = a sqrt(3) / 2).
Outline triangleOutline(double side) {
  const double h = side * std::sqrt(3.0) / 2.0;
  return {{-0.5 * side, -h / 3.0}, {0.5 * side, -h / 3.0}, {0.0, 2.0 * h / 3.0}};
}

// Interior angle at vertex i of a counter-clockwise outline [rad], in (0, 2 pi).
double interiorAngle(const Outline& poly, std::size_t i) {
  const std::size_t n = poly.size();
  const V2 prev = toV2(poly[(i + n - 1) % n]), cur = toV2(poly[i]), next = toV2(poly[(i + 1) % n]);
  const V2 tIn = unit(cur - prev), tOut = unit(next - cur);
  const double turn = std::atan2(crossZ(tIn, tOut), dot(tIn, tOut));  // > 0: left turn (convex)
  return kPi - turn;
}

// Distance from the tip of a convex corner to the centre of its corner atom, along the bisector.
// Natural position: touching both edges (r / sin(theta/2)). If that leaves a tip gap above
// cornerGap, the atom slides toward the tip until the gap is cornerGap; it then pokes out by
// r - s sin(theta/2). For corners so sharp that this overshoot would exceed the gap, the atom sits
// where overshoot = gap (s = 2r / (1 + sin(theta/2))), the smallest possible worst deviation.
double cornerAtomDistance(double theta, const ClumpOptions& o) {
  const double r = o.atomRadius;
  const double sh = std::sin(0.5 * theta);
  const double natural = r / sh;
  const double balanced = 2.0 * r / (1.0 + sh);
  return std::max(balanced, std::min(natural, r + o.cornerGap));
}

// Depth below the outline (positive inside) for the shape; analytic for the disk.
std::function<double(OutlinePoint)> outlineDepth(const Shape& shape) {
  if (shape.isDisk()) {
    const double radius = shape.diskRadius;
    return [radius](OutlinePoint p) { return radius - std::hypot(p[0], p[1]); };
  }
  const Outline* poly = &shape.outline;
  return [poly](OutlinePoint p) { return depthInside(*poly, p); };
}

// Appends atoms from a to b (a included, b excluded) at equal steps no longer than maxSpacing.
void fillPiece(std::vector<OutlinePoint>& out, V2 a, V2 b, double maxSpacing) {
  const double len = norm(b - a);
  const int n = std::max(1, static_cast<int>(std::ceil(len / maxSpacing - 1e-9)));
  for (int k = 0; k < n; ++k) out.push_back(toPoint(a + (static_cast<double>(k) / n) * (b - a)));
}

std::vector<OutlinePoint> polygonSurfaceAtoms(const Outline& poly, const ClumpOptions& o) {
  // The atoms' centres follow the inner parallel curve of the outline at distance r, so every
  // surface atom touches the outline from inside: straight runs along each edge, an arc of radius r
  // about each reflex vertex, and at a convex vertex the corner atom of cornerAtomDistance. Where a
  // corner atom is pulled toward the tip, short slanted pieces join it to the edge runs one spacing
  // before the offset vertex, so the rest of each edge stays exactly at depth r.
  const double r = o.atomRadius;
  const double sp = o.maxSpacing;
  const std::size_t n = poly.size();
  std::vector<V2> chain;  // key points in order; consecutive ones are joined by straight pieces
  for (std::size_t i = 0; i < n; ++i) {
    const V2 prev = toV2(poly[(i + n - 1) % n]), v = toV2(poly[i]), next = toV2(poly[(i + 1) % n]);
    const V2 tIn = unit(v - prev), tOut = unit(next - v);
    const V2 nIn{-tIn.y, tIn.x}, nOut{-tOut.y, tOut.x};  // inward normals (interior on the left)
    const double turn = std::atan2(crossZ(tIn, tOut), dot(tIn, tOut));
    if (turn > 1e-12) {  // convex corner
      const double theta = kPi - turn;
      const V2 bisector = unit(tOut - tIn);
      const double natural = r / std::sin(0.5 * theta);
      const double s = cornerAtomDistance(theta, o);
      const V2 offsetVertex = v + natural * bisector;
      const V2 cornerAtom = v + s * bisector;
      if (natural - s > 1e-12) {
        const double lenIn = norm(v - prev), lenOut = norm(next - v);
        const double backIn = std::min(sp, 0.5 * lenIn), backOut = std::min(sp, 0.5 * lenOut);
        chain.push_back(offsetVertex - backIn * tIn);
        chain.push_back(cornerAtom);
        chain.push_back(offsetVertex + backOut * tOut);
      } else {
        chain.push_back(cornerAtom);
      }
    } else {  // reflex (or straight) vertex: arc of radius r about it, from nIn round to nOut
      const double a0 = std::atan2(nIn.y, nIn.x);
      const double sweep = turn;  // <= 0: the normals turn clockwise with the tangents
      const double maxStep = 2.0 * std::asin(std::min(1.0, sp / (2.0 * r)));
      const int m = std::max(1, static_cast<int>(std::ceil(std::abs(sweep) / maxStep - 1e-12)));
      for (int k = 0; k <= m; ++k) {
        const double a = a0 + sweep * k / m;
        const V2 p = v + r * V2{std::cos(a), std::sin(a)};
        if (chain.empty() || norm(p - chain.back()) > 1e-9) chain.push_back(p);
      }
      (void)nOut;
    }
  }
  // Closing duplicates (a straight vertex puts its single foot point twice).
  while (chain.size() > 1 && norm(chain.front() - chain.back()) <= 1e-9) chain.pop_back();
  std::vector<OutlinePoint> atoms;
  for (std::size_t i = 0; i < chain.size(); ++i)
    fillPiece(atoms, chain[i], chain[(i + 1) % chain.size()], sp);
  return atoms;
}

std::vector<OutlinePoint> diskSurfaceAtoms(double radius, const ClumpOptions& o) {
  const double rc = radius - o.atomRadius;
  // A multiple of 4 atoms, so the ring is mirror-symmetric about both axes.
  const int count = 4 * static_cast<int>(std::ceil(2.0 * kPi * rc / (4.0 * o.maxSpacing) - 1e-12));
  std::vector<OutlinePoint> atoms;
  for (int k = 0; k < count; ++k) {
    const double a = 2.0 * kPi * k / count;
    atoms.push_back({rc * std::cos(a), rc * std::sin(a)});
  }
  return atoms;
}

double minDistanceToAtoms(const std::vector<OutlinePoint>& a, const std::vector<OutlinePoint>& b,
                          OutlinePoint p) {
  double best2 = std::numeric_limits<double>::infinity();
  for (const auto* list : {&a, &b})
    for (const OutlinePoint& c : *list) {
      const double dx = p[0] - c[0], dy = p[1] - c[1];
      best2 = std::min(best2, dx * dx + dy * dy);
    }
  return std::sqrt(best2);
}

// Atom centres binned in square cells, for "is any atom within `radius` of p?" on the fine grids
// of placeAtoms and measureClump. A linear scan there made the cost grow as (size)^3.4 (2.4 s for
// a 40 d square, minutes under the sanitizers: found by fuzzing); with cells no smaller than the
// radius, a query looks at the 3 x 3 cells around p. The answer is the linear scan's, bit for bit
// (same comparison on the same numbers), so the atoms placed do not change.
class AtomCells {
 public:
  AtomCells(double cellSize, const std::vector<OutlinePoint>& atoms) : size_(cellSize) {
    for (const OutlinePoint& c : atoms) add(c);
  }
  void add(OutlinePoint c) { cells_[key(cell(c[0]), cell(c[1]))].push_back(c); }
  bool anyWithin(OutlinePoint p, double radius) const {
    const double r2 = radius * radius;
    const std::int64_t cx = cell(p[0]), cy = cell(p[1]);
    for (std::int64_t j = cy - 1; j <= cy + 1; ++j)
      for (std::int64_t i = cx - 1; i <= cx + 1; ++i) {
        const auto it = cells_.find(key(i, j));
        if (it == cells_.end()) continue;
        for (const OutlinePoint& c : it->second) {
          const double dx = p[0] - c[0], dy = p[1] - c[1];
          if (dx * dx + dy * dy <= r2) return true;
        }
      }
    return false;
  }
 private:
  std::int64_t cell(double v) const { return static_cast<std::int64_t>(std::floor(v / size_)); }
  // Unsigned (wrapping) mixing: far-apart cells that share a key only cost a few comparisons.
  static std::uint64_t key(std::int64_t i, std::int64_t j) {
    return static_cast<std::uint64_t>(i) * 0x9E3779B97F4A7C15ULL ^ static_cast<std::uint64_t>(j);
  }
  double size_;
  std::unordered_map<std::uint64_t, std::vector<OutlinePoint>> cells_;
};

std::string fixed3(double value) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3f", value);
  return buf;
}

}  // namespace

std::function<double(OutlinePoint)> depthFunction(const Shape& shape) { return outlineDepth(shape); }

const std::vector<ShapeName>& namedShapes() {
  static const std::vector<ShapeName> shapes = [] {
    std::vector<ShapeName> all;
    for (std::size_t i = 0; i < ChoiceNames<ShapeName>::names.size(); ++i)
      if (static_cast<ShapeName>(i) != ShapeName::Polygon) all.push_back(static_cast<ShapeName>(i));
    return all;
  }();
  return shapes;
}

const std::vector<ShapeName>& paperShapes() {
  static const std::vector<ShapeName> shapes = {ShapeName::Disk, ShapeName::Square, ShapeName::RectNarrow,
                                                ShapeName::RectWide, ShapeName::Triangle};
  return shapes;
}

Shape makeShape(ShapeName kind, const Outline& vertices, double angleDegrees) {
  if (!std::isfinite(angleDegrees)) throw Error("intruder.angle: not a finite number");
  Shape shape;
  shape.kind = kind;
  if (kind != ShapeName::Polygon && !vertices.empty())
    throw Error("intruder.vertices: only used with shape = \"polygon\", not '" + std::string(choiceName(kind)) + "'");
  Outline raw;
  switch (kind) {
    case ShapeName::Polygon: {
      if (vertices.empty()) throw Error("intruder.vertices: shape 'polygon' needs a vertex list");
      requireValidPolygon(vertices, "intruder.vertices");
      raw = counterClockwise(vertices);
      const OutlinePoint c = areaCentroid(raw);
      raw = translated(std::move(raw), -c[0], -c[1]);
      break;
    }
    case ShapeName::Disk:
      // A disk is rotation-invariant: the angle is ignored and the outline stays exact.
      shape.diskRadius = 0.5 * kDiskDiameter;
      shape.outline = diskOutline(shape.diskRadius);
      return shape;
    case ShapeName::Square: raw = rectangle(6.5, 6.5); break;
    case ShapeName::RectNarrow: raw = rectangle(4.5, 9.5); break;
    case ShapeName::RectWide: raw = rectangle(9.5, 4.5); break;
    case ShapeName::Triangle: raw = triangleOutline(9.5); break;
  }
  shape.outline = rotated(std::move(raw), angleDegrees);
  return shape;
}

Shape makeShape(const IntruderDef& def) {
  Outline vertices(def.vertices.begin(), def.vertices.end());
  return makeShape(def.shape, vertices, def.angle);
}

ClumpOptions clumpOptionsFor(const IntruderDef& def) {
  ClumpOptions options;
  if (def.surface == IntruderSurface::Glued) options.maxSpacing = 2.0 * options.atomRadius;
  return options;
}

double cornerDeviation(double theta, const ClumpOptions& o) {
  const double r = o.atomRadius;
  const double s = cornerAtomDistance(theta, o);
  return std::max(s - r, r - s * std::sin(0.5 * theta));
}

ClumpAtoms placeAtoms(const Shape& shape, const ClumpOptions& o) {
  ClumpAtoms atoms;
  atoms.atomRadius = o.atomRadius;
  atoms.surface = shape.isDisk() ? diskSurfaceAtoms(shape.diskRadius, o)
                               : polygonSurfaceAtoms(shape.outline, o);
  if (!o.guardInterior) return atoms;

  // Guard atoms: a square lattice well inside the shell, then a greedy pass over a fine grid that
  // adds an atom wherever a grain centre could still sit without overlapping any atom.
  const auto depth = outlineDepth(shape);
  const OutlineBox box = boundingBox(shape.outline);
  const double r = o.atomRadius;
  const double cover = r + o.minGrainRadius - o.guardMargin;
  const double a = o.guardSpacing;
  for (double y = a * std::ceil(box.yMin / a); y <= box.yMax; y += a)
    for (double x = a * std::ceil(box.xMin / a); x <= box.xMax; x += a)
      if (depth({x, y}) >= 2.0 * r + o.minGrainRadius - o.guardMargin)
        atoms.guard.push_back({x, y});
  AtomCells cells(cover, atoms.surface);
  for (const OutlinePoint& g : atoms.guard) cells.add(g);
  const double step = 0.05;
  for (double y = box.yMin + 0.5 * step; y < box.yMax; y += step)
    for (double x = box.xMin + 0.5 * step; x < box.xMax; x += step) {
      const double dp = depth({x, y});
      if (dp <= 0.0) continue;
      if (cells.anyWithin({x, y}, cover)) continue;
      if (dp >= r) {
        atoms.guard.push_back({x, y});
        cells.add({x, y});
      }
    }
  return atoms;
}

namespace {

// measureClump's parts: each measures one way the atoms may fail the outline (ClumpQuality).
using DepthFunction = std::function<double(OutlinePoint)>;

// Outline -> envelope: the largest distance from a point of the outline (sampled every <= 0.005 d)
// to the surface atoms' circles.
double largestOutlineGap(const Shape& shape, const ClumpAtoms& atoms) {
  const double r = atoms.atomRadius;
  const std::vector<OutlinePoint> none;
  double gap = 0.0;
  auto gapAt = [&](OutlinePoint p) { gap = std::max(gap, minDistanceToAtoms(atoms.surface, none, p) - r); };
  if (shape.isDisk()) {
    const int samples = static_cast<int>(std::ceil(2.0 * kPi * shape.diskRadius / 0.005));
    for (int k = 0; k < samples; ++k) {
      const double a = 2.0 * kPi * k / samples;
      gapAt({shape.diskRadius * std::cos(a), shape.diskRadius * std::sin(a)});
    }
  } else {
    const std::size_t n = shape.outline.size();
    for (std::size_t i = 0; i < n; ++i) {
      const V2 a = toV2(shape.outline[i]), b = toV2(shape.outline[(i + 1) % n]);
      const int m = std::max(1, static_cast<int>(std::ceil(norm(b - a) / 0.005)));
      for (int k = 0; k < m; ++k) gapAt(toPoint(a + (static_cast<double>(k) / m) * (b - a)));
    }
  }
  return gap;
}

// Envelope -> outline: the deepest point of a surface atom's circle that no other surface atom
// covers and that faces outward (depth below r; the shell's inner side lies deeper than 2r - 0.1).
double deepestEnvelopePoint(const ClumpAtoms& atoms, const DepthFunction& depth) {
  const double r = atoms.atomRadius;
  const std::size_t ns = atoms.surface.size();
  double deepest = 0.0;
  for (std::size_t i = 0; i < ns; ++i) {
    const OutlinePoint c = atoms.surface[i];
    std::vector<std::size_t> near;  // only atoms closer than 2r can cover a point of this circle
    for (std::size_t j = 0; j < ns; ++j)
      if (j != i && std::hypot(atoms.surface[j][0] - c[0], atoms.surface[j][1] - c[1]) < 2.0 * r)
        near.push_back(j);
    for (int k = 0; k < 720; ++k) {
      const double a = 2.0 * kPi * k / 720.0;
      const OutlinePoint p{c[0] + r * std::cos(a), c[1] + r * std::sin(a)};
      const double dp = depth(p);
      if (dp >= r) continue;
      bool covered = false;
      for (std::size_t j : near)
        if (std::hypot(p[0] - atoms.surface[j][0], p[1] - atoms.surface[j][1]) < r - 1e-12) {
          covered = true;
          break;
        }
      if (!covered) deepest = std::max(deepest, dp);
    }
  }
  return deepest;
}

// Neighbouring surface atoms: a grain of radius R resting on two atoms a distance s apart sits
// with its centre sqrt((r+R)^2 - s^2/4) above their centre line, so it sinks
// (r+R) - sqrt((r+R)^2 - s^2/4) below their common tangent; if s/2 >= r+R it falls through.
void measureSurfaceSpacing(const ClumpAtoms& atoms, const ClumpOptions& o, ClumpQuality& q) {
  const double rr = atoms.atomRadius + o.minGrainRadius;
  const std::size_t ns = atoms.surface.size();
  for (std::size_t i = 0; i < ns; ++i) {
    const OutlinePoint a = atoms.surface[i], b = atoms.surface[(i + 1) % ns];
    const double s = std::hypot(b[0] - a[0], b[1] - a[1]);
    q.maxSurfaceSpacing = std::max(q.maxSurfaceSpacing, s);
    const double lodge = (0.5 * s >= rr) ? std::numeric_limits<double>::infinity()
                                         : rr - std::sqrt(rr * rr - 0.25 * s * s);
    q.maxLodgeDepth = std::max(q.maxLodgeDepth, lodge);
  }
}

// Interior coverage on a grid offset from the one placeAtoms used: how far a point inside the
// outline lies beyond the reach of the smallest grain touching an atom.
double largestUncoveredInterior(const Shape& shape, const ClumpAtoms& atoms, const ClumpOptions& o,
                                const DepthFunction& depth) {
  const double rr = atoms.atomRadius + o.minGrainRadius;
  const OutlineBox box = boundingBox(shape.outline);
  AtomCells cells(rr, atoms.surface);
  for (const OutlinePoint& g : atoms.guard) cells.add(g);
  const double step = 0.05;
  double largest = 0.0;
  for (double y = box.yMin + 0.013; y < box.yMax; y += step)
    for (double x = box.xMin + 0.029; x < box.xMax; x += step) {
      if (depth({x, y}) <= 0.0 || cells.anyWithin({x, y}, rr)) continue;
      largest = std::max(largest, minDistanceToAtoms(atoms.surface, atoms.guard, {x, y}) - rr);
    }
  return largest;
}

}  // namespace

ClumpQuality measureClump(const Shape& shape, const ClumpAtoms& atoms, const ClumpOptions& o) {
  ClumpQuality q;
  const double r = atoms.atomRadius;
  const auto depth = outlineDepth(shape);
  q.surfaceAtoms = atoms.surface.size();
  q.guardAtoms = atoms.guard.size();
  q.maxOvershoot = -std::numeric_limits<double>::infinity();
  for (const auto* list : {&atoms.surface, &atoms.guard})
    for (const OutlinePoint& c : *list) q.maxOvershoot = std::max(q.maxOvershoot, r - depth(c));
  q.maxOutlineGap = largestOutlineGap(shape, atoms);
  q.maxEnvelopeDepth = deepestEnvelopePoint(atoms, depth);
  measureSurfaceSpacing(atoms, o, q);
  q.minInteriorAngle = 180.0;
  if (!shape.isDisk()) {
    for (std::size_t i = 0; i < shape.outline.size(); ++i) {
      const double theta = interiorAngle(shape.outline, i);
      if (theta < kPi) {
        q.minInteriorAngle = std::min(q.minInteriorAngle, theta * 180.0 / kPi);
        q.worstCornerDeviation = std::max(q.worstCornerDeviation, cornerDeviation(theta, o));
      }
    }
  }
  q.maxUncoveredInterior = largestUncoveredInterior(shape, atoms, o, depth);
  return q;
}

ClumpAtoms buildClumpAtoms(const Shape& shape, const ClumpOptions& o) {
  ClumpAtoms atoms = placeAtoms(shape, o);
  const ClumpQuality q = measureClump(shape, atoms, o);
  // A smooth surface keeps the outline within 0.1 of the atoms (corners aside); a coarser spacing
  // (touching atoms) has its own gap between neighbours, sqrt(s^2 / 4 + r^2) - r.
  const double r = o.atomRadius, s = o.maxSpacing;
  const double limit = std::max({0.1, q.worstCornerDeviation, std::sqrt(0.25 * s * s + r * r) - r}) + 1e-9;
  const std::string what = "intruder '" + std::string(choiceName(shape.kind)) + "'";
  if (q.maxOvershoot > limit)
    throw Error(what + ": outline has features too small for atoms of radius " + fixed3(o.atomRadius) +
                " d (an atom reaches " + fixed3(q.maxOvershoot) + " d beyond it, limit " +
                fixed3(limit) + ")");
  if (q.maxOutlineGap > limit)
    throw Error(what + ": outline has features too small for atoms of radius " + fixed3(o.atomRadius) +
                " d (part of it is " + fixed3(q.maxOutlineGap) + " d from the atoms, limit " +
                fixed3(limit) + ")");
  if (q.maxSurfaceSpacing > 2.0 * o.atomRadius + 1e-9)  // touching atoms close the shell
    throw Error(what + ": surface atoms leave a gap (spacing " + fixed3(q.maxSurfaceSpacing) + " d)");
  if (o.guardInterior && q.maxUncoveredInterior > 0.0)
    throw Error(what + ": the interior could not be covered with guard atoms");
  return atoms;
}

}  // namespace wiggle
