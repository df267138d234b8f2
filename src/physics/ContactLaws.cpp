#include "physics/ContactLaws.h"

#include "core/Error.h"

namespace wiggle {

namespace {

template <class... Laws>
constexpr std::array<ContactLawTraits, sizeof...(Laws)> traitsOf(LawList<Laws...>) {
  return {ContactLawTraits{Laws::kName, Laws::kSummary, Laws::kStiffnessUnit, &Laws::contactTime,
                           &Laws::lammpsPairStyle}...};
}

constexpr auto kTraits = traitsOf(ContactLaws{});

}  // namespace

const ContactLawTraits& contactLawTraits(ContactLaw law) {
  const auto i = static_cast<std::size_t>(law);
  if (i >= kTraits.size()) throw Error("unknown contact law (value " + std::to_string(i) + ")");
  return kTraits[i];
}

std::span<const ContactLawTraits> contactLawList() { return kTraits; }

}  // namespace wiggle
