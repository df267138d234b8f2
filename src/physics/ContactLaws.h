#pragma once
// The contact laws a run can choose (contact.law): ContactLaws below is the one list where a law is
// registered. Everything else is derived from it: contact.law's names (ChoiceNames<ContactLaw>),
// the pair loops of every instruction set (ForceKernelVariant.cpp), and the table the rest of the
// program asks at run time (ContactLawTraits: the step's check, the config's help, the LAMMPS
// export). What a law type carries: ContactLaw.h.
#include <array>
#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>

#include "core/Choice.h"
#include "physics/ContactLaw.h"
#include "physics/HertzLaw.h"
#include "physics/HertzLimitDampingLaw.h"
#include "physics/HookeLaw.h"

namespace wiggle {

template <class... Laws>
struct LawList {};

inline namespace WIGGLE_ISA_NAMESPACE {

// Every law, one line each. A law's position is its ContactLaw value, the byte that checkpoints and
// bed files hold and bed keys hash: append, never reorder. The first is the default.
// clang-format off
using ContactLaws = LawList<HertzLaw,
                            HookeLaw,
                            HertzLimitDampingLaw>;
// clang-format on

template <class Law, class... Laws>
consteval std::size_t lawIndex(LawList<Laws...>) {
  std::size_t i = 0;
  const bool listed = ((std::is_same_v<Law, Laws> || (++i, false)) || ...);
  if (!listed) throw "not a law of ContactLaws";  // a compile error: consteval
  return i;
}

// The ContactLaw value of a law type.
template <class Law>
inline constexpr ContactLaw contactLaw = static_cast<ContactLaw>(lawIndex<Law>(ContactLaws{}));

static_assert(contactLaw<HertzLaw> == ContactLaw{}, "Hertz is the default law, and the one older files imply");

template <class... Laws>
constexpr std::array<std::string_view, sizeof...(Laws)> lawNames(LawList<Laws...>) {
  return {Laws::kName...};
}

}  // inline namespace WIGGLE_ISA_NAMESPACE

template <>
struct ChoiceNames<ContactLaw> {
  static constexpr auto names = lawNames(ContactLaws{});
};

// What the program asks a law at run time, outside the pair loops (ContactLaw.h says what each
// field means). Built from the law types in ContactLaws.cpp, in the list's order.
struct ContactLawTraits {
  std::string_view name;
  std::string_view summary;
  std::string_view stiffnessUnit;
  double (*contactTime)(const ContactParams& contact, double radius, double mass, double speed);
  std::string (*lammpsPairStyle)(const ContactParams& contact);
};

// The traits of a law; throws wiggle::Error for a value no law has.
const ContactLawTraits& contactLawTraits(ContactLaw law);

// Every law's traits, in the list's order (the first is the default).
std::span<const ContactLawTraits> contactLawList();

}  // namespace wiggle
