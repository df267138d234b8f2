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
  double fx, fy;      // force on i
  double torqueArm;   // rinv (dx fs_y - dy fs_x); torque_i -= radI * torqueArm
  double overlap;     // radI + radJ - r when touching, else <= 0 [d]
};

// Returns the force; updates (shearX, shearY) in place. When the pair does not touch the force is
// zero and the history is reset, as LAMMPS does for a neighbour that stopped touching.
// `updateShear` is false only for the set-up force evaluation before the first step (LAMMPS does
// not advance the history while update->setupflag is set).
inline ContactForce hertzHistoryContact(const ContactParams& p, double dt, double dx, double dy,
                                        double dvx, double dvy, double radI, double radJ,
                                        double omegaI, double omegaJ, double meff,
                                        double& shearX, double& shearY, bool updateShear) {
  const double rsq = dx * dx + dy * dy;
  const double radsum = radI + radJ;
  if (rsq >= radsum * radsum) {
    shearX = 0.0;
    shearY = 0.0;
    return {0.0, 0.0, 0.0, radsum - std::sqrt(rsq)};
  }
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
  double ccel = p.kn * (radsum - r) * rinv - damp;
  const double polyhertz = std::sqrt((radsum - r) * radI * radJ / radsum);
  ccel *= polyhertz;

  // Relative tangential velocity at the contact point, rotation included.
  const double vtr1 = vt1 + dy * wr3;
  const double vtr2 = vt2 - dx * wr3;

  if (updateShear) {
    shearX += vtr1 * dt;
    shearY += vtr2 * dt;
  }
  const double shrmagSq = shearX * shearX + shearY * shearY;

  // Project the history onto the current tangent plane (its length is not restored).
  const double rsht = (shearX * dx + shearY * dy) * rsqinv;
  if (updateShear) {
    shearX -= rsht * dx;
    shearY -= rsht * dy;
  }

  const double dampT = meff * p.gammaT;
  double fs1 = -polyhertz * (p.kt * shearX + dampT * vtr1);
  double fs2 = -polyhertz * (p.kt * shearY + dampT * vtr2);

  // Coulomb cap: |Ft| <= mu |Fn|, with the history rescaled to give exactly the capped force.
  const double fs = std::sqrt(fs1 * fs1 + fs2 * fs2);
  const double fn = p.mu * std::fabs(ccel * r);
  if (fs > fn) {
    if (shrmagSq != 0.0) {
      const double ratio = fn / fs;
      shearX = ratio * (shearX + dampT * vtr1 / p.kt) - dampT * vtr1 / p.kt;
      shearY = ratio * (shearY + dampT * vtr2 / p.kt) - dampT * vtr2 / p.kt;
      fs1 *= ratio;
      fs2 *= ratio;
    } else {
      fs1 = 0.0;
      fs2 = 0.0;
    }
  }

  return {dx * ccel + fs1, dy * ccel + fs2, rinv * (dx * fs2 - dy * fs1), radsum - r};
}

}  // namespace wiggle
