#pragma once
// The key table behind io/Config: one entry per configuration key (name, kind, unit, help, bounds,
// accessor), from which parsing, --set, validation, help and TOML output are all derived. Internal to
// io/Config*.cpp; everything else goes through io/Config.h.
#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <limits>
#include <vector>

#include <toml++/toml.h>

#include "io/RunConfig.h"

namespace wiggle::config_keys {

enum class Kind { Number, Integer, Boolean, Text, Choice, NumberList, PointList };

// Whether the bed a config makes depends on the key (Shapes: the bed key hashes it).
enum class BedRole { Apart, Shapes };

struct Bound {
  bool present = false;
  double value = 0.0;
  bool inclusive = false;
};
constexpr Bound noBound{};
constexpr Bound above(double v) { return {true, v, false}; }
constexpr Bound atLeast(double v) { return {true, v, true}; }
constexpr Bound below(double v) { return {true, v, false}; }
constexpr Bound atMost(double v) { return {true, v, true}; }

using Points = std::vector<std::array<double, 2>>;

// One TOML key. The accessors take a mutable config; reading a const config goes through
// `mut()` below.
struct KeyInfo {
  std::string_view name;   // "section.key"
  Kind kind;
  std::string_view unit;   // "" for a pure number
  std::string_view help;   // one line
  Bound lower, upper;      // Number, Integer, and each NumberList element
  std::vector<std::string_view> choices;  // Choice
  BedRole bed = BedRole::Apart;
  double& (*number)(RunConfig&) = nullptr;
  std::uint64_t& (*integer)(RunConfig&) = nullptr;
  bool& (*boolean)(RunConfig&) = nullptr;
  std::string& (*text)(RunConfig&) = nullptr;
  std::string (*getChoice)(const RunConfig&) = nullptr;  // a choice: kept as an enum (core/Choice.h)
  void (*setChoice)(RunConfig&, const std::string&) = nullptr;

  std::vector<double>& (*numberList)(RunConfig&) = nullptr;
  Points& (*pointList)(RunConfig&) = nullptr;

  std::string_view section() const { return name.substr(0, name.find('.')); }
  std::string_view leaf() const { return name.substr(name.find('.') + 1); }
};

// Reading a const config goes through the same accessors: a read accessor only forms a reference.
inline RunConfig& mut(const RunConfig& c) { return const_cast<RunConfig&>(c); }

// The chosen name of a Choice key, and setting it.
std::string chosen(const KeyInfo& k, const RunConfig& c);
void choose(const KeyInfo& k, RunConfig& c, const std::string& v);

// Every key, in the order of docs/CONFIG.md.
const std::vector<KeyInfo>& keyTable();
const KeyInfo* findKey(std::string_view key);  // nullptr when there is no such key
std::vector<std::string_view> sectionNames();
bool isSection(std::string_view name);

// TOML integers are signed 64-bit, so a seed above this could not be written back.
constexpr std::uint64_t maxTomlInteger = static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max());

// The text of values (io/ConfigText.cpp).
// Shortest text that reads back to the same double; tomlStyle marks whole numbers as floats ("5.0").
std::string roundTripText(double v, bool tomlStyle);
std::string quoteToml(const std::string& s);
// A key's value in `config`: TOML text (tomlStyle) or short display text.
std::string valueText(const KeyInfo& k, const RunConfig& config, bool tomlStyle);
// Any TOML value as text; strings are quoted when `quote` (always inside arrays and tables).
std::string nodeText(const toml::node& n, bool quote);
std::string typeName(const toml::node& n);  // "string", "array", ...
std::string boundText(const Bound& lo, const Bound& hi);  // "> 0 and <= 1"
// "" when v is finite and within the bounds, else what is wrong ("must be > 0").
std::string rangeProblem(double v, const Bound& lo, const Bound& hi);

}  // namespace wiggle::config_keys
