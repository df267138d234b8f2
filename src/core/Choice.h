#pragma once
// An enumerated choice (a config key whose value is one of a few names, e.g. contact.law): the enum
// names its values in code, ChoiceNames<E>::names (specialised beside the enum) names them in the
// config, in the enum's order. That table is the only list of the names: parsing, writing a config
// back, the help and the errors all read it.
#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace wiggle {

template <class E>
struct ChoiceNames;  // static constexpr std::array<std::string_view, N> names{...};

// A value outside the enum's (a cast, a corrupt file) has no name: validation then reports it.
template <class E>
constexpr std::string_view choiceName(E value) {
  const auto i = static_cast<std::size_t>(value);
  return i < ChoiceNames<E>::names.size() ? ChoiceNames<E>::names[i] : std::string_view("(no such value)");
}

template <class E>
constexpr std::optional<E> choiceNamed(std::string_view name) {
  for (std::size_t i = 0; i < ChoiceNames<E>::names.size(); ++i)
    if (ChoiceNames<E>::names[i] == name) return static_cast<E>(i);
  return std::nullopt;
}

template <class E>
std::vector<std::string_view> choiceNameList() {
  return {ChoiceNames<E>::names.begin(), ChoiceNames<E>::names.end()};
}

// Names as one text for a help or an error: "a, b, c" (or with another separator).
inline std::string joinedNames(const std::vector<std::string_view>& names, std::string_view separator = ", ") {
  std::string text;
  for (const std::string_view name : names) text += (text.empty() ? "" : std::string(separator)) + std::string(name);
  return text;
}

// Whether a number read from a file is one of E's values.
template <class E, class Raw>
constexpr bool isChoice(Raw raw) {
  return static_cast<std::size_t>(raw) < ChoiceNames<E>::names.size();
}

}  // namespace wiggle
