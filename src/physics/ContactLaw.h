#pragma once
// The contact law of LAMMPS `pair_style gran/hertz/history` (SPEC 2), restricted to 2D.
//
// Source: LAMMPS src/GRANULAR/pair_gran_hertz_history.cpp, PairGranHertzHistory::compute()
// (version 29 Sep 2021). The arithmetic below follows that routine operation by operation, with
// the z terms dropped: in 2D every dropped term is an exact zero (delz, vr3, omega_x, omega_y), so
// removing it does not change a single bit of the result. Symbols (only here):
//   dx, dy     x_i - x_j (minimum image) [d]            dvx, dvy   v_i - v_j [sqrt(g d)]
//   radI, radJ radii [d]                                omegaI/J   spins about z [sqrt(g/d)]
//   meff       mi mj/(mi+mj), or the free partner's mass when the other is frozen [rho d^3]
//   kn, kt     Hertz normal and tangential stiffness      gammaN/T   viscoelastic damping
//   mu         Coulomb friction coefficient               dt         time step
//   shearX/Y   stored tangential displacement (history) of the pair, in i's frame
// Normal force: Fn = sqrt(delta Reff) (kn delta - meff gammaN vn), not clamped at zero.
// Tangential: s += vt dt, s projected on the tangent plane (length not restored), then
// Ft = -sqrt(delta Reff)(kt s + meff gammaT vt), capped at mu |Fn| with s rescaled so that spring
// plus damping give exactly the capped force.
// Outputs: (fx, fy) is the force on i (j gets the opposite); the torques are
// torque_i -= radI * torqueArm, torque_j -= radJ * torqueArm.
#include <cmath>

namespace wiggle {

struct ContactParams {
  double kn = 2e6;        // normal stiffness [rho d g]... Kn of SPEC 2 (units of the paper)
  double kt = 2.46e6;     // tangential stiffness
  double gammaN = 2500;   // normal damping [sqrt(g/d)]
  double gammaT = 2500;   // tangential damping [sqrt(g/d)]
  double mu = 0.1;        // Coulomb friction coefficient
};

struct ContactForce {
  double fx, fy;          // force on i
  double torqueArm;       // rinv (dx fs_y - dy fs_x); torque_i -= radI * torqueArm
  double shearX, shearY;  // the pair's history after this step (0 when not touching) [d]
};

// Returns the force and the pair's new history (shearX, shearY are the history before the step). When the pair does not touch the force is
// zero and the history is reset, as LAMMPS does for a neighbour that stopped touching.
// `updateShear` is false only for the set-up force evaluation before the first step (LAMMPS does
// not advance the history while update->setupflag is set).
//
// Written without branches: every quantity is computed and the cases (touching or not, capped or
// not, history update or not) are selected afterwards, so that the pair loop vectorises. Each
// selected value is produced by exactly the operations LAMMPS performs in that case, so the result
// is bitwise the same as the branching form. Lanes of pairs that do not touch compute NaN (sqrt of
// a negative overlap) that is never selected.
inline ContactForce hertzHistoryContact(const ContactParams& p, double dt, double dx, double dy,
                                        double dvx, double dvy, double radI, double radJ,
                                        double omegaI, double omegaJ, double meff,
                                        double shearX, double shearY, bool updateShear) {
  const double rsq = dx * dx + dy * dy;
  const double radsum = radI + radJ;
  const bool touching = rsq < radsum * radsum;
  const double r = std::sqrt(rsq);
  const double rinv = 1.0 / r;
  const double rsqinv = 1.0 / rsq;

  // Normal and tangential parts of the relative velocity.
  const double vnnr = dvx * dx + dvy * dy;
  const double vn1 = dx * vnnr * rsqinv;
  const double vn2 = dy * vnnr * rsqinv;
  const double vt1 = dvx - vn1;
  const double vt2 = dvy - vn2;
  const double wr3 = (radI * omegaI + radJ * omegaJ) * rinv;

  // Normal force: Hertz spring plus velocity damping, scaled by sqrt(delta Reff).
  const double damp = meff * p.gammaN * vnnr * rsqinv;
  const double polyhertz = std::sqrt((radsum - r) * radI * radJ / radsum);
  const double ccel = (p.kn * (radsum - r) * rinv - damp) * polyhertz;

  // Relative tangential velocity at the contact point, rotation included.
  const double vtr1 = vt1 + dy * wr3;
  const double vtr2 = vt2 - dx * wr3;

  // History: accumulate, then project onto the current tangent plane (length not restored).
  const double accX = updateShear ? shearX + vtr1 * dt : shearX;
  const double accY = updateShear ? shearY + vtr2 * dt : shearY;
  const double shrmagSq = accX * accX + accY * accY;
  const double rsht = (accX * dx + accY * dy) * rsqinv;
  double sx = updateShear ? accX - rsht * dx : accX;
  double sy = updateShear ? accY - rsht * dy : accY;

  const double dampT = meff * p.gammaT;
  double fs1 = -polyhertz * (p.kt * sx + dampT * vtr1);
  double fs2 = -polyhertz * (p.kt * sy + dampT * vtr2);

  // Coulomb cap: |Ft| <= mu |Fn|, with the history rescaled to give exactly the capped force.
  const double fs = std::sqrt(fs1 * fs1 + fs2 * fs2);
  const double fn = p.mu * std::fabs(ccel * r);
  const bool capped = fs > fn;
  const bool rescale = capped && shrmagSq != 0.0;
  const double ratio = fn / fs;
  const double cappedX = ratio * (sx + dampT * vtr1 / p.kt) - dampT * vtr1 / p.kt;
  const double cappedY = ratio * (sy + dampT * vtr2 / p.kt) - dampT * vtr2 / p.kt;
  sx = rescale ? cappedX : sx;
  sy = rescale ? cappedY : sy;
  fs1 = capped ? (rescale ? fs1 * ratio : 0.0) : fs1;
  fs2 = capped ? (rescale ? fs2 * ratio : 0.0) : fs2;

  return {touching ? dx * ccel + fs1 : 0.0, touching ? dy * ccel + fs2 : 0.0,
          touching ? rinv * (dx * fs2 - dy * fs1) : 0.0, touching ? sx : 0.0, touching ? sy : 0.0};
}

}  // namespace wiggle
