#pragma once
// The Hooke law, LAMMPS's `pair_style gran/hooke/history` (docs/PHYSICS.md §4): the Hertz law
// without its factor sqrt(delta Reff), a linear spring-dashpot whose stiffnesses are forces per
// length. A policy of the contact law (ContactLaw.h), listed in ContactLaws.h.
#include <cmath>
#include <numbers>
#include <string>
#include <string_view>

#include "physics/ContactLaw.h"

namespace wiggle {
inline namespace WIGGLE_ISA_NAMESPACE {

struct HookeLaw {
  static constexpr std::string_view kName = "hooke";
  static constexpr std::string_view kSummary =
      "gran/hooke/history, the same law without its sqrt(overlap Reff) factor (a linear spring-dashpot; "
      "kn and kt are then forces per length, m g / d)";
  static constexpr std::string_view kStiffnessUnit = "m g / d";
  static constexpr int kHistoryValues = 2;  // the shear displacement s

  template <class V>
  static V scale(V, V) {
    return V(1.0);  // x * 1 is x exactly, so the compiler drops the products
  }
  template <class V>
  static V normalForce(V ccel) {
    return ccel;
  }

  // F = kn delta: half a period of the spring, t_c = pi sqrt(meff / kn) with meff = m/2, whatever
  // the speed (damping only lengthens it).
  static double contactTime(const ContactParams& contact, double, double mass, double) {
    return std::numbers::pi * std::sqrt(0.5 * mass / contact.kn);
  }

  static std::string lammpsPairStyle(const ContactParams& p) { return granularPairStyle("gran/hooke/history", p); }
};

}  // inline namespace WIGGLE_ISA_NAMESPACE
}  // namespace wiggle
