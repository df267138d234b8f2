#pragma once
// Plane-polygon geometry for intruder outlines: area, centroid, bounding box, validity (including a
// self-intersection check usable on any vertex list), point containment and distance to the
// boundary. Pure functions on plain vertex lists, so the cavity model, the CLI and the plotting
// exports can share them. A polygon is a closed vertex list without the first vertex repeated.
#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace wiggle {

using OutlinePoint = std::array<double, 2>;  // (x, y) [d]
using Outline = std::vector<OutlinePoint>;

struct OutlineBox {
  double xMin = 0.0, yMin = 0.0, xMax = 0.0, yMax = 0.0;  // [d]
  double width() const { return xMax - xMin; }
  double height() const { return yMax - yMin; }
};

// Shoelace area: positive for counter-clockwise vertex order [d^2].
double signedArea(const Outline& polygon);
// Area centroid (centre of mass of the uniformly filled polygon) [d].
OutlinePoint areaCentroid(const Outline& polygon);
OutlineBox boundingBox(const Outline& polygon);

// The first pair of edges (edge k runs from vertex k to vertex k+1) that cross or touch although
// they are not neighbours, or neighbours that fold back onto each other; nullopt for a simple
// outline. O(n^2), meant for outlines of up to a few thousand vertices.
std::optional<std::array<std::size_t, 2>> findSelfIntersection(const Outline& polygon);

// What is wrong with a vertex list as an intruder outline, as one line ("" prefix-free), or nullopt:
// fewer than 3 vertices, non-finite numbers, repeated consecutive vertices, zero area,
// self-intersection.
std::optional<std::string> polygonProblem(const Outline& polygon);
// Throws wiggle::Error "<what>: <problem>" when polygonProblem finds one.
void requireValidPolygon(const Outline& polygon, std::string_view what);

// The same outline in counter-clockwise order (reversed if it was clockwise).
Outline counterClockwise(Outline polygon);
Outline translated(Outline polygon, double dx, double dy);
// Rotation about the origin, counter-clockwise [degrees].
Outline rotated(Outline polygon, double angleDegrees);

// Even-odd containment; points exactly on the boundary may go either way.
bool containsPoint(const Outline& polygon, OutlinePoint p);
// Unsigned distance from p to the nearest point of the boundary [d].
double distanceToBoundary(const Outline& polygon, OutlinePoint p);
// Signed depth: distance to the boundary, positive inside, negative outside [d].
double depthInside(const Outline& polygon, OutlinePoint p);

}  // namespace wiggle
