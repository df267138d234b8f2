#pragma once
// Reading, checking and writing a run's configuration (docs/CONFIG.md; the struct is io/RunConfig.h).
//
// One table of key descriptors (ConfigKeys.cpp, `keyTable()`) drives everything: for each TOML key it
// holds the field it maps to, the value's kind, the allowed range, the unit and a one-line meaning.
// The file reader, `--set`, validation, `configHelp()` and `toToml()` all walk that table, so a new
// key is one new row and cannot be parsed by one path and forgotten by another.
//
// Precedence: defaults of RunConfig.h < the TOML file < `--set section.key=value` (in the order
// given). Each value's type and own range are checked as it is applied (so a bad value in a file
// is reported with its line); checks that involve two keys run once at the end
// (validateRunConfig). Geometric checks that need the intruder's shape (box too narrow, intruder
// too near the top or bottom, self-intersecting polygon) belong to the scenario code, not here.
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <toml++/toml.h>

#include "io/RunConfig.h"

namespace wiggle {

// Starts from the defaults, applies every key of `tomlText`, then validates. `sourceName` (a file
// name) prefixes every error message. Throws wiggle::Error.
RunConfig parseRunConfig(const std::string& tomlText, const std::string& sourceName);

// No path: the defaults. Then each override "section.key=value" in order (the value is read as a
// TOML value; a bare word that is not TOML, like `triangle`, is taken as a string). Then
// validation. Throws wiggle::Error naming the file or "--set" and the key.
RunConfig loadRunConfig(const std::optional<std::string>& path,
                        const std::vector<std::string>& overrides);

// Applies one "section.key=value" override (the `--set` syntax) to `config`; no final validation.
void applyOverride(RunConfig& config, const std::string& assignment);

// Sets one key ("section.key") from a TOML value, checking its type and its own range. `where`
// (e.g. "config.toml:12" or "--set") starts the error message. The one code path for files,
// `--set` and sweep grids.
void applySetting(RunConfig& config, const std::string& key, const toml::node& value,
                  const std::string& where);

// Every range check and every cross-key check that needs only the config. Throws wiggle::Error
// whose message starts with the key, e.g. "drive.period = -1: must be > 0".
void validateRunConfig(const RunConfig& config);

// What an atom type of a LAMMPS data file is in wiggle's bed (bed.lammps_types).
enum class LammpsRole { Grain, Base, Drop };

// bed.lammps_types read: "TYPE=ROLE ..." (roles grain, base, drop; each type once), as type -> role.
// Throws wiggle::Error starting with the key.
std::map<int, LammpsRole> lammpsTypeRoles(const std::string& text);

// The number of run.dt steps in `interval`, or 0 when it is not a whole number of them (to 1e-9
// relative): the one rule for every interval that must fall on a step (drive.period,
// run.sample_interval, run.dump_interval, run.duration's counts in scenario/case/Case).
std::uint64_t wholeStepsIn(double interval, double dt);

// The resolved config as TOML: every key, each with a comment giving its meaning and unit.
// parseRunConfig(toToml(c)) reproduces c bit for bit (doubles written in shortest round-trip form).
std::string toToml(const RunConfig& config);

// Every key grouped by section, with its default, unit, allowed values and meaning
// (`wiggle run --help`, docs/CONFIG.md).
std::string configHelp();

// All keys "section.key" in table order.
std::vector<std::string> configKeys();

// The names a choice key takes ("disk", "square", ...); empty for any other key.
std::vector<std::string> configKeyChoices(std::string_view key);

// Whether the bed a config makes depends on the key: declared beside the key in the key table, and
// exactly the keys scenario/bed/BedMaker's bed key hashes (BedMakerTest perturbs every key to check it).
bool keyShapesBed(std::string_view key);

// A key's current value as short display text: numbers in shortest round-trip form ("5", "0.25",
// "1e-08"), strings without quotes ("disk"), lists as TOML arrays ("[0, 5]"). For results.csv
// columns and case names. Throws wiggle::Error for an unknown key.
std::string configValueString(const RunConfig& config, std::string_view key);

// A key's current value as TOML text ("2.5", "\"disk\"", "[0.0, 5.0]"), as toToml writes it: for
// files that set a few keys (a sweep's [[case]]). Throws wiggle::Error for an unknown key.
std::string configValueToml(const RunConfig& config, std::string_view key);

// True for a key whose value is a real number (not a whole number, a word or a list): a value a
// search may take anywhere in a range.
bool isRealKey(std::string_view key);

// Exact equality of every key (doubles compared bit for bit via ==; no NaN survives validation).
bool sameRunConfig(const RunConfig& a, const RunConfig& b);
// The first key (table order) whose value differs between a and b, leaving out `ignored`; "" when
// none does.
std::string firstDifferingKey(const RunConfig& a, const RunConfig& b, const std::vector<std::string_view>& ignored = {});

// "did you mean ...?" support: the known key closest to `key`, or "" when none is close.
std::string suggestConfigKey(std::string_view key);

// Display text of a TOML value in the style of configValueString (used for sweep case names).
std::string tomlValueString(const toml::node& value);

// True for a known key "section.key".
bool isConfigKey(std::string_view key);

// The TOML text of a file as a table; a syntax error becomes a wiggle::Error
// "<sourceName>:<line>:<column>: TOML syntax error: ...".
toml::table parseTomlText(const std::string& tomlText, const std::string& sourceName);

// One "section.key = value" of a table shaped like a run config, with the line it is on.
struct ConfigEntry {
  std::string key;            // "section.key"
  const toml::node* value;    // points into the table passed to configEntries
  unsigned line;              // 1-based line in the source (0 if unknown)
};

// The keys of a table shaped like a run config ([box], [drive], ...) in the order they appear in
// the file. Unknown sections and keys are errors naming them with `tablePath` in front
// (e.g. "base.drive.perod" for a sweep's [base]) and a suggestion. Top-level names in
// `skipNames` are left to the caller (a sweep's [[case]] `name`).
std::vector<ConfigEntry> configEntries(const toml::table& table, const std::string& sourceName,
                                       const std::string& tablePath = "",
                                       const std::vector<std::string>& skipNames = {});

// Applies every key of such a table (errors as "<sourceName>:<line>: <key> = ...").
void applyConfigTable(RunConfig& config, const toml::table& table, const std::string& sourceName,
                      const std::string& tablePath = "");

}  // namespace wiggle
