#pragma once
// The paper's cavity model (section 3.5; docs/PHYSICS.md §11): from the outline alone, the rise threshold
// T_rise and the rise rate V_y(T) of a horizontally wiggling intruder. Pure functions on a vertex
// list; no simulation types. docs/MODEL.md derives and tabulates it.
//
// Point of no return y_nr: the lowest point of the outline where its tangent is vertical, which for
// a polygon is the lowest point at its extreme horizontal position on the side of the cavity
// (leftmost x for the cavity on the left, rightmost x on the right; on a vertical edge its lower
// end; for a disk its equator). A grain that falls below y_nr ends under the intruder.
#include <array>
#include <nlohmann/json_fwd.hpp>
#include <vector>

namespace wiggle {

struct CavitySide {
  double yNoReturn = 0.0;  // y_nr [d]
  double l = 0.0;          // y0 - y_nr: how far a grain above the top falls to get under [d]
  double lPrime = 0.0;     // l + d/2 [d]
  double tRise = 0.0;      // sqrt(2 l' / g): periods below it give no rise [sqrt(d/g)]
};

struct CavityGeometry {
  double y0 = 0.0;    // top of the outline [d]
  double h = 0.0;     // outline height [d]
  double tMax = 0.0;  // sqrt(8 h / g): above it the cavity fills up [sqrt(d/g)]
  CavitySide left;    // the cavity on the left (opened while the intruder moves right)
  CavitySide right;   // the cavity on the right
  // True when the two sides give different l (beyond 1e-9 d): report them separately.
  bool sidesDiffer() const;
};

// Throws wiggle::Error for fewer than 3 vertices or non-finite coordinates.
CavityGeometry cavityGeometry(const std::vector<std::array<double, 2>>& outline,
                              double grainDiameter = 1.0, double gravity = 1.0);

// The geometry's keys as every file that carries them writes them (a run's model.json, `wiggle
// model --geometry`; docs/OUTPUT-FORMATS.md): y0, h, T_max and per side y_nr, l, T_rise.
nlohmann::json cavityGeometryJson(const CavityGeometry& geometry);

// Smallest amplitude for a rise: the cavity 2A must hold a grain, A_min = d/2.
double minimumAmplitude(double grainDiameter = 1.0);

// V_y(T) for one side's cavity (eq. 3.17): 0 for A <= A_min or T <= T_rise;
// (g T / 2)[(1 - 2/pi^2) - (T_rise/T)^2 - (2/pi^2) cos(pi T_rise/T) - (2/pi)(T_rise/T) sin(pi T_rise/T)]
// for T_rise < T < T_max; (h - l) / T for T >= T_max [sqrt(g d)].
double cavityRiseRate(const CavityGeometry& geometry, const CavitySide& side, double period,
                      double amplitude, double grainDiameter = 1.0, double gravity = 1.0);

}  // namespace wiggle
