#pragma once
// The Hertz law, LAMMPS's `pair_style gran/hertz/history` (docs/PHYSICS.md §4): the paper's law and
// the default. A policy of the contact law (ContactLaw.h says what a law type carries), listed in
// ContactLaws.h.
#include <cmath>
#include <string>
#include <string_view>

#include "physics/ContactLaw.h"

namespace wiggle {
inline namespace WIGGLE_ISA_NAMESPACE {

struct HertzLaw {
  static constexpr std::string_view kName = "hertz";
  static constexpr std::string_view kSummary = "LAMMPS's gran/hertz/history, the paper's";
  static constexpr std::string_view kStiffnessUnit = "m g / d^2";
  static constexpr int kHistoryValues = 2;  // the shear displacement s

  // Both forces scale with sqrt(delta Reff).
  template <class V>
  static V scale(V overlap, V reff) {
    using simd::sqrt;
    return sqrt(overlap * reff);
  }
  // The normal force as computed, not clamped: a strongly damped pair can briefly pull.
  template <class V>
  static V normalForce(V ccel) {
    return ccel;
  }

  // A head-on contact of two grains of radius `radius` and mass `mass` meeting at `speed`, without
  // damping (damping only lengthens it), meff = m/2, Reff = r/2: F = kn sqrt(Reff) delta^(3/2) gives
  // t_c = 2.9433 delta_max / speed, delta_max = (5 meff v^2 / (4 kn sqrt(Reff)))^(2/5).
  static double contactTime(const ContactParams& contact, double radius, double mass, double speed) {
    const double meff = 0.5 * mass;
    const double reff = 0.5 * radius;
    const double k = contact.kn * std::sqrt(reff);
    const double deltaMax = std::pow(5.0 * meff * speed * speed / (4.0 * k), 0.4);
    return 2.9433 * deltaMax / speed;
  }

  static std::string lammpsPairStyle(const ContactParams& p) { return granularPairStyle("gran/hertz/history", p); }
};

}  // inline namespace WIGGLE_ISA_NAMESPACE
}  // namespace wiggle
