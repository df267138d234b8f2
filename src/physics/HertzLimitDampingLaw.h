#pragma once
// The Hertz law with LAMMPS's `limit_damping` keyword, `pair_style gran/hertz/history ...
// limit_damping` (docs/PHYSICS.md §4): the normal force is clamped at zero, so that the damping of a
// separating pair can slow it but never pull it back. With the normal force at zero the Coulomb cap
// is zero too, so such a pair has no tangential force either, and its shear history is rescaled as
// any capped pair's. Everything else is the Hertz law's, the contact time included (the clamp acts
// only through the damping, which the undamped contact time leaves out). A policy of the contact
// law (ContactLaw.h), listed in ContactLaws.h.
#include <string>
#include <string_view>

#include "physics/ContactLaw.h"
#include "physics/HertzLaw.h"

namespace wiggle {
inline namespace WIGGLE_ISA_NAMESPACE {

struct HertzLimitDampingLaw : HertzLaw {
  static constexpr std::string_view kName = "hertz_limit_damping";
  static constexpr std::string_view kSummary =
      "gran/hertz/history with limit_damping, the Hertz law with its normal force clamped at zero (the damping never "
      "makes a separating pair pull)";

  // LAMMPS: if (limit_damping && ccel < 0.0) ccel = 0.0, before the Coulomb cap reads it.
  template <class V>
  static V normalForce(V ccel) {
    using simd::select;
    return select(ccel < V(0.0), V(0.0), ccel);
  }

  static std::string lammpsPairStyle(const ContactParams& p) {
    return granularPairStyle("gran/hertz/history", p, "limit_damping");
  }
};

}  // inline namespace WIGGLE_ISA_NAMESPACE
}  // namespace wiggle
