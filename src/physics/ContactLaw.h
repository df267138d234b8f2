#pragma once
// The granular contact law of LAMMPS's `pair_style gran/*/history` family (docs/PHYSICS.md §4),
// restricted to 2D: what every law shares, and what a law is (a policy type). The laws themselves
// are one header each (HertzLaw.h, HookeLaw.h, ...) and are listed in ContactLaws.h, the one place
// a law is registered.
//
// Source: LAMMPS src/GRANULAR/pair_gran_hertz_history.cpp, PairGranHertzHistory::compute(), and
// pair_gran_hooke_history.cpp, PairGranHookeHistory::compute() (version 29 Sep 2021). The routines
// differ only in what a law policy supplies below: Hertz scales the normal force and the tangential
// force (spring and damping alike) by sqrt(delta Reff), Hooke does not (its stiffnesses are then
// forces per length), and the `limit_damping` keyword clamps the normal force at zero. So the law is
// written once here, templated over the policy: each law's pair loops are compiled on their own, and
// a policy whose functions are identities costs nothing (the Hertz path is the same code, with the
// same bits, as before any other law existed).
//
// The arithmetic follows those routines' formulas with the z terms dropped (in 2D each is an exact
// zero: delz, vr3, omega_x, omega_y). It is not LAMMPS's operation order everywhere: LAMMPS divides
// seven times per pair (1/r, 1/r^2, Reff, meff, fn/fs and twice by kt), and divisions are what
// bound the kernel's speed (docs/PERFORMANCE.md). Here one division gives 1/r, 1/(Ri + Rj) and meff
// together, 1/r^2 is (1/r)^2 and 1/kt is computed once, so a result can differ from LAMMPS's by a
// few ulps; the LAMMPS comparison tests bound what that does to trajectories. Symbols (only here):
//   dx, dy     x_i - x_j (minimum image) [d]            dvx, dvy   v_i - v_j [sqrt(g d)]
//   radI, radJ radii [d]                                omegaI/J   spins about z [sqrt(g/d)]
//   invMassSum 1/mi + 1/mj (1/mi alone when j is frozen), so meff = 1 / invMassSum [1/(rho d^3)]
//   kn, kt     normal and tangential stiffness         gammaN/T   viscoelastic damping
//   mu         Coulomb friction coefficient               dt         time step
//   shearX/Y   stored tangential displacement (history) of the pair, in i's frame
//   scale      the law's factor of both forces: sqrt(delta Reff) for Hertz, 1 for Hooke
//              (delta = Ri + Rj - r, the overlap)
// Normal force: Fn = scale (kn delta - meff gammaN vn), then the law's normalForce (the identity, or
// a clamp at zero). Tangential: s += vt dt, s projected on the tangent plane (length not restored),
// then Ft = -scale (kt s + meff gammaT vt), capped at mu |Fn| with s rescaled so that spring plus
// damping give exactly the capped force.
// Outputs: (fx, fy) is the force on i (j gets the opposite); the torques are
// torque_i -= radI * torqueArm, torque_j -= radJ * torqueArm.
//
// A law is a type that the engine, the checks, the help and the
// LAMMPS export ask instead of switching on its name:
//   kName            contact.law's word for it (config, checkpoints by position in ContactLaws.h)
//   kSummary         what it is, for the help of contact.law
//   kStiffnessUnit   the unit of contact.kn and contact.kt under it
//   kHistoryValues   doubles of per-pair history it keeps: 2 (the shear displacement s, the
//                    pair slots' shearX/Y) for every law so far
//   scale(delta, reff), normalForce(ccel)   its force, templated over V (double or lanes) and
//                    branch-free, used by contactTrial below
//   contactTime(contact, radius, mass, speed)   a head-on contact's duration, for the step check
//   lammpsPairStyle(contact)   the `pair_style` and `pair_coeff` lines of the LAMMPS deck
#include <cstdint>
#include <string>
#include <string_view>

#include "core/Format.h"
#include "core/Simd.h"

namespace wiggle {

// contact.law: which force law the pairs follow, as its position in ContactLaws (ContactLaws.h,
// which also names the values: ChoiceNames<ContactLaw>). The zero value is the first law, Hertz.
enum class ContactLaw : std::uint8_t {};

struct ContactParams {
  double kn = 2e6;        // normal stiffness [rho d g]... Kn of docs/PHYSICS.md §4 (units of the paper)
  double kt = 2.46e6;     // tangential stiffness
  double gammaN = 2500;   // normal damping [sqrt(g/d)]
  double gammaT = 2500;   // tangential damping [sqrt(g/d)]
  double mu = 0.1;        // Coulomb friction coefficient
  ContactLaw law{};       // the same numbers serve every law; kn, kt mean other units in some (kStiffnessUnit)
};

// The doubles of history a pair slot holds (PairSlots, NeighbourList, IntruderPairs: shearX, shearY);
// a law that keeps more needs those widened first (PairKernel.h checks each law against it).
inline constexpr int kPairHistoryValues = 2;

// The law's functions are compiled once per instruction set (core/Simd.h: the inline namespace).
inline namespace WIGGLE_ISA_NAMESPACE {

// The `pair_style gran/<style>/history` line a law of this family writes into a LAMMPS deck, with
// its coefficients to 17 digits, dampflag 1 (tangential damping on) and the law's keywords, if any,
// and the `pair_coeff` line that applies it to every pair of types.
inline std::string granularPairStyle(std::string_view style, const ContactParams& p, std::string_view keywords = {}) {
  std::string text = "pair_style ";
  text += style;
  for (const double v : {p.kn, p.kt, p.gammaN, p.gammaT, p.mu}) (text += ' ') += formatNumber(v, 17);
  text += " 1";
  if (!keywords.empty()) (text += ' ') += keywords;
  text += "\npair_coeff * *\n";
  return text;
}

template <class V>  // double, or lanes of doubles (core/Simd.h)
struct ContactForceOf {
  V fx, fy;          // force on i
  V torqueArm;       // rinv (dx fs_y - dy fs_x); torque_i -= radI * torqueArm
  V shearX, shearY;  // the pair's history after this step (0 when not touching) [d]
};
using ContactForce = ContactForceOf<double>;

// The law in three stages: the geometry (a sqrt and the one division for three reciprocals), the
// trial force (a sqrt, Hertz only) and the Coulomb cap (a sqrt and a division); historyContact
// composes them. These five operations bound the kernel's speed (docs/PERFORMANCE.md: running the
// stages as three loops over a chunk of pairs was measured, and did not pay: the divider is
// saturated, not idle). V is double (the reference) or a vector of lanes (core/Simd.h) with the same bits per lane.

// Stage 1: the distance and one division for three reciprocals, q = 1 / (r (Ri + Rj) invMassSum).
template <class V>
struct ContactGeometry {
  V r, q;
};
template <class V>
inline ContactGeometry<V> contactGeometry(V dx, V dy, V radI, V radJ, V invMassSum) {
  using simd::sqrt;
  const V r = sqrt(dx * dx + dy * dy);
  return {r, V(1.0) / (r * (radI + radJ) * invMassSum)};
}

// Stage 2: relative velocities, the normal force, the history update and the uncapped tangential
// force. (Callers pass the parameters as a local copy, so that the compiler can hoist 1/kt out of
// their pair loops: a reference might alias the slots they store to.)
template <class V>
struct ContactTrial {
  V ccel;            // normal force over r
  V fs1, fs2;        // tangential force before the Coulomb cap
  V sx, sy;          // history after the update (before the cap)
  V shrmagSq;        // squared history before the projection (the cap leaves a zero history alone)
  V dampX, dampY;    // the damping part of the tangential force in history units: meff gammaT vtr / kt
  V rinv;
};
template <class Law, class V>
inline ContactTrial<V> contactTrial(const ContactParams& p, double dt, V dx, V dy, V dvx, V dvy, V radI, V radJ,
                                    V omegaI, V omegaJ, V invMassSum, V shearX, V shearY, bool updateShear,
                                    ContactGeometry<V> g) {
  using simd::sqrt;
  const V radsum = radI + radJ;
  const V r = g.r;
  const V rRadsum = r * radsum;
  const V rinv = g.q * radsum * invMassSum;
  const V meff = g.q * rRadsum;
  const V reff = radI * radJ * (g.q * r * invMassSum);  // Ri Rj / (Ri + Rj)
  const V rsqinv = rinv * rinv;

  // Normal and tangential parts of the relative velocity.
  const V vnnr = dvx * dx + dvy * dy;
  const V vn1 = dx * vnnr * rsqinv;
  const V vn2 = dy * vnnr * rsqinv;
  const V vt1 = dvx - vn1;
  const V vt2 = dvy - vn2;
  const V wr3 = (radI * omegaI + radJ * omegaJ) * rinv;

  // Normal force: spring plus velocity damping, scaled by the law (Hertz: sqrt(delta Reff)), then
  // as the law applies it (clamped at zero under limit_damping, before the Coulomb cap reads it).
  const V damp = meff * p.gammaN * vnnr * rsqinv;
  const V polyhertz = Law::scale(radsum - r, reff);
  const V ccel = Law::normalForce((p.kn * (radsum - r) * rinv - damp) * polyhertz);

  // Relative tangential velocity at the contact point, rotation included.
  const V vtr1 = vt1 + dy * wr3;
  const V vtr2 = vt2 - dx * wr3;

  // History: accumulate, then project onto the current tangent plane (length not restored).
  const V accX = updateShear ? shearX + vtr1 * dt : shearX;
  const V accY = updateShear ? shearY + vtr2 * dt : shearY;
  const V shrmagSq = accX * accX + accY * accY;
  const V rsht = (accX * dx + accY * dy) * rsqinv;
  const V sx = updateShear ? accX - rsht * dx : accX;
  const V sy = updateShear ? accY - rsht * dy : accY;

  const V dampT = meff * p.gammaT;
  const double ktInv = 1.0 / p.kt;
  return {ccel,
          -polyhertz * (p.kt * sx + dampT * vtr1),
          -polyhertz * (p.kt * sy + dampT * vtr2),
          sx,
          sy,
          shrmagSq,
          dampT * vtr1 * ktInv,
          dampT * vtr2 * ktInv,
          rinv};
}

// Stage 3: the Coulomb cap (|Ft| <= mu |Fn|, with the history rescaled to give exactly the capped
// force) and the outputs; zero force and history for a pair that does not touch.
template <class V>
inline ContactForceOf<V> contactForce(const ContactParams& p, V dx, V dy, V radI, V radJ, ContactGeometry<V> g,
                                      const ContactTrial<V>& t) {
  using simd::abs;
  using simd::select;
  using simd::sqrt;
  const V radsum = radI + radJ;
  const auto touching = dx * dx + dy * dy < radsum * radsum;
  const V fs = sqrt(t.fs1 * t.fs1 + t.fs2 * t.fs2);
  const V fn = p.mu * abs(t.ccel * g.r);
  const auto capped = fs > fn;
  const auto rescale = capped & (t.shrmagSq != V(0.0));
  const V ratio = fn / fs;
  const V zero(0.0);
  const V sx = select(rescale, ratio * (t.sx + t.dampX) - t.dampX, t.sx);
  const V sy = select(rescale, ratio * (t.sy + t.dampY) - t.dampY, t.sy);
  const V fs1 = select(capped, select(rescale, t.fs1 * ratio, zero), t.fs1);
  const V fs2 = select(capped, select(rescale, t.fs2 * ratio, zero), t.fs2);
  return {select(touching, dx * t.ccel + fs1, zero), select(touching, dy * t.ccel + fs2, zero),
          select(touching, t.rinv * (dx * fs2 - dy * fs1), zero), select(touching, sx, zero),
          select(touching, sy, zero)};
}

// Returns the force and the pair's new history (shearX, shearY are the history before the step).
// When the pair does not touch the force is zero and the history is reset, as LAMMPS does for a
// neighbour that stopped touching. `updateShear` is false only for the set-up force evaluation
// before the first step (LAMMPS does not advance the history while update->setupflag is set).
//
// Written without branches: every quantity is computed and the cases (touching or not, capped or
// not, history update or not) are selected afterwards, so that the pair loop vectorises. Lanes of
// pairs that do not touch compute NaN (sqrt of a negative overlap) that is never selected.
template <class Law, class V>
inline ContactForceOf<V> historyContact(const ContactParams& p, double dt, V dx, V dy, V dvx, V dvy, V radI, V radJ,
                                        V omegaI, V omegaJ, V invMassSum, V shearX, V shearY, bool updateShear) {
  const ContactGeometry<V> g = contactGeometry(dx, dy, radI, radJ, invMassSum);
  const ContactTrial<V> t = contactTrial<Law>(p, dt, dx, dy, dvx, dvy, radI, radJ, omegaI, omegaJ, invMassSum, shearX,
                                              shearY, updateShear, g);
  return contactForce(p, dx, dy, radI, radJ, g, t);
}

}  // inline namespace WIGGLE_ISA_NAMESPACE
}  // namespace wiggle
