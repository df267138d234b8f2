#include "scenario/geometry/Polygon.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/Error.h"

namespace wiggle {

namespace {

double cross(OutlinePoint o, OutlinePoint a, OutlinePoint b) {
  return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

// Size of the outline, for tolerances that scale with it.
double outlineScale(const Outline& polygon) {
  const OutlineBox box = boundingBox(polygon);
  return std::max({1.0, box.width(), box.height()});
}

// Sign of an orientation determinant, with |value| <= eps counted as collinear.
int orientSign(double value, double eps) { return value > eps ? 1 : (value < -eps ? -1 : 0); }

// Is q (known collinear with segment ab) within the segment's bounding box?
bool onSegment(OutlinePoint a, OutlinePoint b, OutlinePoint q, double tol) {
  return q[0] >= std::min(a[0], b[0]) - tol && q[0] <= std::max(a[0], b[0]) + tol &&
         q[1] >= std::min(a[1], b[1]) - tol && q[1] <= std::max(a[1], b[1]) + tol;
}

bool segmentsMeet(OutlinePoint p1, OutlinePoint p2, OutlinePoint q1, OutlinePoint q2, double eps,
                  double tol) {
  const int d1 = orientSign(cross(q1, q2, p1), eps);
  const int d2 = orientSign(cross(q1, q2, p2), eps);
  const int d3 = orientSign(cross(p1, p2, q1), eps);
  const int d4 = orientSign(cross(p1, p2, q2), eps);
  if (d1 * d2 < 0 && d3 * d4 < 0) return true;
  if (d1 == 0 && onSegment(q1, q2, p1, tol)) return true;
  if (d2 == 0 && onSegment(q1, q2, p2, tol)) return true;
  if (d3 == 0 && onSegment(p1, p2, q1, tol)) return true;
  if (d4 == 0 && onSegment(p1, p2, q2, tol)) return true;
  return false;
}

double distanceToSegment(OutlinePoint a, OutlinePoint b, OutlinePoint p) {
  const double ex = b[0] - a[0], ey = b[1] - a[1];
  const double len2 = ex * ex + ey * ey;
  double t = len2 > 0.0 ? ((p[0] - a[0]) * ex + (p[1] - a[1]) * ey) / len2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(p[0] - (a[0] + t * ex), p[1] - (a[1] + t * ey));
}

}  // namespace

double signedArea(const Outline& polygon) {
  double twice = 0.0;
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i) {
    const OutlinePoint& a = polygon[i];
    const OutlinePoint& b = polygon[(i + 1) % n];
    twice += a[0] * b[1] - b[0] * a[1];
  }
  return 0.5 * twice;
}

OutlinePoint areaCentroid(const Outline& polygon) {
  // Shoelace centroid, taken relative to the first vertex to avoid cancellation far from 0.
  const std::size_t n = polygon.size();
  if (n == 0) return {0.0, 0.0};
  const OutlinePoint o = polygon[0];
  double twiceArea = 0.0, cx = 0.0, cy = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double ax = polygon[i][0] - o[0], ay = polygon[i][1] - o[1];
    const double bx = polygon[(i + 1) % n][0] - o[0], by = polygon[(i + 1) % n][1] - o[1];
    const double c = ax * by - bx * ay;
    twiceArea += c;
    cx += (ax + bx) * c;
    cy += (ay + by) * c;
  }
  if (twiceArea == 0.0) return o;
  return {o[0] + cx / (3.0 * twiceArea), o[1] + cy / (3.0 * twiceArea)};
}

OutlineBox boundingBox(const Outline& polygon) {
  OutlineBox box;
  if (polygon.empty()) return box;
  box.xMin = box.xMax = polygon[0][0];
  box.yMin = box.yMax = polygon[0][1];
  for (const OutlinePoint& p : polygon) {
    box.xMin = std::min(box.xMin, p[0]);
    box.xMax = std::max(box.xMax, p[0]);
    box.yMin = std::min(box.yMin, p[1]);
    box.yMax = std::max(box.yMax, p[1]);
  }
  return box;
}

std::optional<std::array<std::size_t, 2>> findSelfIntersection(const Outline& polygon) {
  const std::size_t n = polygon.size();
  if (n < 3) return std::nullopt;
  const double scale = outlineScale(polygon);
  const double eps = 1e-12 * scale * scale;  // orientation determinants scale as length^2
  const double tol = 1e-12 * scale;
  for (std::size_t i = 0; i < n; ++i) {
    const OutlinePoint p1 = polygon[i], p2 = polygon[(i + 1) % n];
    for (std::size_t j = i + 1; j < n; ++j) {
      const OutlinePoint q1 = polygon[j], q2 = polygon[(j + 1) % n];
      const bool adjacent = (j == i + 1) || (i == 0 && j == n - 1);
      if (adjacent) {
        // Neighbours share a vertex; they are only wrong when the outline folds back on itself
        // (collinear with opposite directions), which makes a zero-width spike.
        const OutlinePoint shared = (j == i + 1) ? p2 : p1;
        const OutlinePoint a = (j == i + 1) ? p1 : p2;
        const OutlinePoint b = (j == i + 1) ? q2 : q1;
        const double c = cross(shared, a, b);
        const double dot =
            (a[0] - shared[0]) * (b[0] - shared[0]) + (a[1] - shared[1]) * (b[1] - shared[1]);
        if (orientSign(c, eps) == 0 && dot > 0.0) return std::array<std::size_t, 2>{i, j};
        continue;
      }
      if (segmentsMeet(p1, p2, q1, q2, eps, tol)) return std::array<std::size_t, 2>{i, j};
    }
  }
  return std::nullopt;
}

std::optional<std::string> polygonProblem(const Outline& polygon) {
  const std::size_t n = polygon.size();
  if (n < 3) return "an outline needs at least 3 vertices, got " + std::to_string(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(polygon[i][0]) || !std::isfinite(polygon[i][1]))
      return "vertex " + std::to_string(i + 1) + " is not a finite number";
  }
  const double scale = outlineScale(polygon);
  for (std::size_t i = 0; i < n; ++i) {
    const OutlinePoint a = polygon[i], b = polygon[(i + 1) % n];
    if (std::hypot(b[0] - a[0], b[1] - a[1]) <= 1e-9 * scale)
      return "vertices " + std::to_string(i + 1) + " and " + std::to_string((i + 1) % n + 1) +
             " are repeated (the same point)";
  }
  // All vertices on one line: say so before the self-intersection check, which would report the
  // fold-back such an outline always has.
  double farthest = 0.0;
  std::size_t k = 0;
  for (std::size_t i = 1; i < n; ++i) {
    const double d = std::hypot(polygon[i][0] - polygon[0][0], polygon[i][1] - polygon[0][1]);
    if (d > farthest) farthest = d, k = i;
  }
  double offLine = 0.0;
  for (std::size_t i = 1; i < n; ++i)
    offLine = std::max(offLine, std::abs(cross(polygon[0], polygon[k], polygon[i])) / farthest);
  if (offLine <= 1e-9 * scale) return "the outline has zero area (all vertices on one line)";
  if (auto hit = findSelfIntersection(polygon)) {
    const std::size_t i = (*hit)[0], j = (*hit)[1];
    return "the outline is self-intersecting: edge " + std::to_string(i + 1) + "-" +
           std::to_string((i + 1) % n + 1) + " meets edge " + std::to_string(j + 1) + "-" +
           std::to_string((j + 1) % n + 1) + " (vertices numbered from 1)";
  }
  // A simple outline that is not on one line has positive area; this guards round-off.
  if (std::abs(signedArea(polygon)) <= 1e-9 * scale * scale) return "the outline has zero area";
  return std::nullopt;
}

void requireValidPolygon(const Outline& polygon, std::string_view what) {
  if (auto problem = polygonProblem(polygon)) throw Error(std::string(what) + ": " + *problem);
}

Outline counterClockwise(Outline polygon) {
  if (signedArea(polygon) < 0.0) std::reverse(polygon.begin(), polygon.end());
  return polygon;
}

Outline translated(Outline polygon, double dx, double dy) {
  for (OutlinePoint& p : polygon) {
    p[0] += dx;
    p[1] += dy;
  }
  return polygon;
}

Outline rotated(Outline polygon, double angleDegrees) {
  if (angleDegrees == 0.0) return polygon;
  // Exact quarter turns keep axis-aligned outlines exactly axis-aligned (cos 90 deg is not 0 in
  // floating point), so rotating rect_narrow by 90 gives rect_wide bit for bit.
  const double turns = angleDegrees / 90.0;
  double c, s;
  if (turns == std::round(turns)) {
    const long q = ((static_cast<long>(std::round(turns)) % 4) + 4) % 4;
    const double cs[4] = {1.0, 0.0, -1.0, 0.0};
    const double sn[4] = {0.0, 1.0, 0.0, -1.0};
    c = cs[q];
    s = sn[q];
  } else {
    const double a = angleDegrees * std::numbers::pi / 180.0;
    c = std::cos(a);
    s = std::sin(a);
  }
  for (OutlinePoint& p : polygon) {
    const double x = p[0], y = p[1];
    p[0] = c * x - s * y;
    p[1] = s * x + c * y;
  }
  return polygon;
}

bool containsPoint(const Outline& polygon, OutlinePoint p) {
  bool inside = false;
  const std::size_t n = polygon.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const OutlinePoint& a = polygon[i];
    const OutlinePoint& b = polygon[j];
    if ((a[1] > p[1]) != (b[1] > p[1])) {
      const double xCross = a[0] + (p[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1]);
      if (p[0] < xCross) inside = !inside;
    }
  }
  return inside;
}

double distanceToBoundary(const Outline& polygon, OutlinePoint p) {
  double best = std::numeric_limits<double>::infinity();
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i)
    best = std::min(best, distanceToSegment(polygon[i], polygon[(i + 1) % n], p));
  return best;
}

double depthInside(const Outline& polygon, OutlinePoint p) {
  const double d = distanceToBoundary(polygon, p);
  return containsPoint(polygon, p) ? d : -d;
}

}  // namespace wiggle
