#pragma once
// The intruder as the engine sees it (docs/PHYSICS.md §6): a rigid clump of small atoms. Its
// horizontal position is prescribed; its vertical position is either held or integrated from the
// sum of the contact forces on its atoms plus gravity on its total mass; it turns about its centre
// under their torque only when its motion lets it (rotationFree). Atoms do not interact with each
// other. Shapes (how atoms fill an outline) live in scenario/.
#include <cmath>
#include <cstdint>
#include <functional>
#include <numbers>
#include <vector>

namespace wiggle {

struct ClumpDef {
  std::vector<double> offsetX, offsetY;  // atom centres relative to the clump's centre [d]
  double atomRadius = 0.25;              // [d]
  double mass = 0.0;                     // total mass M, used for gravity and the y equation [rho d^3]
  // How many atoms the body's mass is shared by in the contacts' meff (docs/PHYSICS.md §6): 1, the
  // whole body meets each grain (LAMMPS's fix rigid); n, each contact sees one of the n spheres the
  // body is built of, M / n (LAMMPS's fix move with the atoms' own masses). The y equation keeps M.
  std::uint32_t massShares = 1;
  // Moment of inertia about the centre [rho d^5]: used only when the clump may turn
  // (ClumpMotion::rotationFree; docs/PHYSICS.md §6).
  double inertia = 0.0;

  double contactMass() const { return mass / massShares; }  // an atom's mass in meff [rho d^3]
};

enum class HorizontalMotion : std::uint8_t {
  Held,              // x = x0, vx = 0
  Sinusoid,          // x = x0 + A sin(2 pi t / T), vx = (2 pi A / T) cos(2 pi t / T)
  ConstantVelocity,  // x = x0 + v t, vx = v
  RampedSinusoid,    // x = x0 + A min(1, t / t_ramp) sin(2 pi t / T): from rest, Sinusoid after t_ramp
  VelocitySinusoid,  // vx = A sin(2 pi t / T), x = x0 + (A T / 2 pi)(1 - cos(2 pi t / T)): A a speed, from rest
  Prescribed,        // x = x0 + dx(t), vx(t) from a function the caller gives (the Python module's own drives)
};

struct ClumpMotion {
  HorizontalMotion kind = HorizontalMotion::Held;
  double x0 = 0.0;         // centre of the motion [d]
  double amplitude = 0.0;  // A [d] (Sinusoid, RampedSinusoid); [sqrt(g d)] (VelocitySinusoid)
  double period = 1.0;     // T [sqrt(d/g)] (the sinusoids)
  double velocity = 0.0;   // [sqrt(g d)] (ConstantVelocity)
  bool verticalFree = false;  // false: y held, vy = 0 (while the bed is made)
  double rampTime = 0.0;   // t_ramp [sqrt(d/g)] (RampedSinusoid); a whole number of periods keeps vx
                           // continuous where the ramp ends, since sin(2 pi t_ramp / T) = 0 there
  struct Position {
    double x = 0.0;   // [d]
    double vx = 0.0;  // [sqrt(g d)]
  };
  // Prescribed: t -> (dx, vx), the displacement from x0 and the velocity; and the bound on |vx| it
  // declares, which the time-step check and the blow-up detector use as the drive's peak speed (the
  // engine refuses a vx beyond it). Not saved: a world with it cannot be checkpointed.
  std::function<Position(double)> prescribed = nullptr;
  double peakSpeed = 0.0;  // [sqrt(g d)]
  // The clump turns about its centre under the contact torques (intruder.rotation = "free"); false:
  // it never turns (the paper's model, and while the bed is made).
  bool rotationFree = false;

  double omega() const { return 2.0 * std::numbers::pi / period; }  // angular frequency of the sinusoids
  bool sinusoidal() const {  // one of the drives with a period
    return kind == HorizontalMotion::Sinusoid || kind == HorizontalMotion::RampedSinusoid ||
           kind == HorizontalMotion::VelocitySinusoid;
  }

  // Where the motion puts the clump at time t: the one formula of each kind, used by the engine
  // at every step (World::placeIntruder) and by anything else that needs x(t) or vx(t).
  Position at(double t) const {
    switch (kind) {
      case HorizontalMotion::Held: return {x0, 0.0};
      case HorizontalMotion::Sinusoid: {
        const double w = omega();
        return {x0 + amplitude * std::sin(w * t), amplitude * w * std::cos(w * t)};
      }
      case HorizontalMotion::RampedSinusoid: {
        // Its own branch, not Sinusoid with a factor 1: the plain drive (docs/PHYSICS.md §7) keeps its bits.
        const double w = omega();
        const bool ramping = t < rampTime;
        const double scale = ramping ? t / rampTime : 1.0;
        const double growth = ramping ? 1.0 / rampTime : 0.0;  // d(scale)/dt
        return {x0 + amplitude * scale * std::sin(w * t),
                amplitude * (scale * w * std::cos(w * t) + growth * std::sin(w * t))};
      }
      case HorizontalMotion::ConstantVelocity: return {x0 + velocity * t, velocity};
      case HorizontalMotion::VelocitySinusoid: {
        const double w = omega();
        return {x0 + amplitude / w * (1.0 - std::cos(w * t)), amplitude * std::sin(w * t)};
      }
      case HorizontalMotion::Prescribed: {
        const Position d = prescribed(t);
        return {x0 + d.x, d.vx};
      }
    }
    return {x0, 0.0};
  }
};

// The clump's turn about its centre when it may turn (ClumpMotion::rotationFree): kept apart from
// ClumpState, whose bytes the state hash of every non-turning run holds.
struct ClumpSpin {
  double angle = 0.0;   // turned since the run's start, counter-clockwise [rad]
  double omega = 0.0;   // [sqrt(g/d)]
  double torque = 0.0;  // of the contact forces about the centre [m g d]
};

struct ClumpState {
  double x = 0.0, y = 0.0;    // centre [d]
  double vx = 0.0, vy = 0.0;  // [sqrt(g d)]
  double contactFx = 0.0;     // sum of contact forces on the atoms [m g]
  double contactFy = 0.0;
};

}  // namespace wiggle
