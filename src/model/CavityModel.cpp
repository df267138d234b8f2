#include "model/CavityModel.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "core/Error.h"

namespace wiggle {

namespace {

// Lowest y among the vertices at the extreme x (within a tolerance that scales with the outline,
// so a vertical edge built from rounded numbers still counts as vertical).
double lowestAtExtremeX(const std::vector<std::array<double, 2>>& outline, bool leftSide,
                        double tol) {
  double extreme = outline[0][0];
  for (const auto& p : outline) extreme = leftSide ? std::min(extreme, p[0]) : std::max(extreme, p[0]);
  double lowest = std::numeric_limits<double>::infinity();
  for (const auto& p : outline)
    if (std::abs(p[0] - extreme) <= tol) lowest = std::min(lowest, p[1]);
  return lowest;
}

CavitySide makeSide(double y0, double yNoReturn, double grainDiameter, double gravity) {
  CavitySide side;
  side.yNoReturn = yNoReturn;
  side.l = y0 - yNoReturn;
  side.lPrime = side.l + 0.5 * grainDiameter;
  side.tRise = std::sqrt(2.0 * side.lPrime / gravity);
  return side;
}

}  // namespace

bool CavityGeometry::sidesDiffer() const { return std::abs(left.l - right.l) > 1e-9; }

CavityGeometry cavityGeometry(const std::vector<std::array<double, 2>>& outline,
                              double grainDiameter, double gravity) {
  if (outline.size() < 3)
    throw Error("cavity model: an outline needs at least 3 vertices, got " +
                std::to_string(outline.size()));
  for (const auto& p : outline)
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]))
      throw Error("cavity model: outline has a non-finite coordinate");
  if (!(grainDiameter > 0.0) || !(gravity > 0.0))
    throw Error("cavity model: grain diameter and gravity must be positive");
  double yMin = outline[0][1], yMax = outline[0][1], xMin = outline[0][0], xMax = outline[0][0];
  for (const auto& p : outline) {
    yMin = std::min(yMin, p[1]);
    yMax = std::max(yMax, p[1]);
    xMin = std::min(xMin, p[0]);
    xMax = std::max(xMax, p[0]);
  }
  const double tol = 1e-9 * std::max({1.0, xMax - xMin, yMax - yMin});
  CavityGeometry g;
  g.y0 = yMax;
  g.h = yMax - yMin;
  g.tMax = std::sqrt(8.0 * g.h / gravity);
  g.left = makeSide(g.y0, lowestAtExtremeX(outline, true, tol), grainDiameter, gravity);
  g.right = makeSide(g.y0, lowestAtExtremeX(outline, false, tol), grainDiameter, gravity);
  return g;
}

double minimumAmplitude(double grainDiameter) { return 0.5 * grainDiameter; }

double cavityRiseRate(const CavityGeometry& geometry, const CavitySide& side, double period,
                      double amplitude, double grainDiameter, double gravity) {
  if (!(period > 0.0) || !std::isfinite(period))
    throw Error("cavity model: the period must be positive and finite");
  if (amplitude <= minimumAmplitude(grainDiameter)) return 0.0;
  if (period <= side.tRise) return 0.0;
  if (period >= geometry.tMax) return (geometry.h - side.l) / period;
  constexpr double pi = std::numbers::pi;
  const double ratio = side.tRise / period;
  return 0.5 * gravity * period *
         ((1.0 - 2.0 / (pi * pi)) - ratio * ratio - 2.0 / (pi * pi) * std::cos(pi * ratio) -
          2.0 / pi * ratio * std::sin(pi * ratio));
}

nlohmann::json cavityGeometryJson(const CavityGeometry& g) {
  nlohmann::json j;
  j["y0"] = g.y0;
  j["h"] = g.h;
  j["T_max"] = g.tMax;
  j["y_nr_left"] = g.left.yNoReturn;
  j["y_nr_right"] = g.right.yNoReturn;
  j["l_left"] = g.left.l;
  j["l_right"] = g.right.l;
  j["T_rise_left"] = g.left.tRise;
  j["T_rise_right"] = g.right.tRise;
  return j;
}

}  // namespace wiggle
