#include "io/Config.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>

#include "core/Error.h"
#include "io/AtomicFile.h"
#include "io/ConfigKeys.h"

namespace wiggle {
namespace {

using namespace config_keys;

// ---------------------------------------------------------------------------------------------
// Suggestions
// ---------------------------------------------------------------------------------------------

std::size_t editDistance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> prev(b.size() + 1), cur(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) prev[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    cur[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t sub = prev[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, sub});
    }
    std::swap(prev, cur);
  }
  return prev[b.size()];
}

std::string_view leafOf(std::string_view key) {
  const auto dot = key.rfind('.');
  return dot == std::string_view::npos ? key : key.substr(dot + 1);
}

std::string didYouMean(std::string_view suggestion, std::string_view prefix = "") {
  if (suggestion.empty()) return "";
  return " (did you mean '" + std::string(prefix) + std::string(suggestion) + "'?)";
}

// Closest section name to `name`, or a full key whose leaf is `name` (a key written outside its
// section), or "".
std::string suggestSection(std::string_view name) {
  std::string best;
  std::size_t bestDistance = 3;
  for (const std::string_view s : sectionNames()) {
    const std::size_t d = editDistance(name, s);
    if (d < bestDistance) {
      bestDistance = d;
      best = std::string(s);
    }
  }
  if (!best.empty()) return best;
  return suggestConfigKey(name);
}

std::string withPath(const std::string& tablePath, std::string_view key) {
  return tablePath.empty() ? std::string(key) : tablePath + "." + std::string(key);
}

std::string lineWhere(const std::string& sourceName, const toml::node& n) {
  const auto line = n.source().begin.line;
  return line ? sourceName + ":" + std::to_string(line) : sourceName;
}

std::string trim(std::string_view s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string_view::npos) return "";
  const auto e = s.find_last_not_of(" \t\r\n");
  return std::string(s.substr(b, e - b + 1));
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// Public functions
// ---------------------------------------------------------------------------------------------

std::string suggestConfigKey(std::string_view key) {
  std::string best;
  std::size_t bestDistance = std::max<std::size_t>(3, key.size() / 4 + 1);
  for (const KeyInfo& k : keyTable()) {
    const std::size_t d = editDistance(key, k.name);
    if (d < bestDistance) {
      bestDistance = d;
      best = std::string(k.name);
    }
  }
  if (!best.empty()) return best;
  // The right key name in the wrong section (box.dt -> run.dt), or no section at all.
  const std::string_view leaf = leafOf(key);
  for (const KeyInfo& k : keyTable()) {
    if (k.leaf() == leaf) return std::string(k.name);
  }
  return "";
}

bool isConfigKey(std::string_view key) { return findKey(key) != nullptr; }

std::vector<std::string> configKeys() {
  std::vector<std::string> out;
  for (const KeyInfo& k : keyTable()) out.emplace_back(k.name);
  return out;
}

std::vector<std::string> configKeyChoices(std::string_view key) {
  const KeyInfo* k = findKey(key);
  if (k == nullptr) return {};
  return {k->choices.begin(), k->choices.end()};
}

bool keyShapesBed(std::string_view key) {
  const KeyInfo* k = findKey(key);
  return k != nullptr && k->bed == BedRole::Shapes;
}

std::string tomlValueString(const toml::node& value) { return nodeText(value, false); }

std::string configValueString(const RunConfig& config, std::string_view key) {
  const KeyInfo* k = findKey(key);
  if (!k) throw Error("unknown key '" + std::string(key) + "'" + didYouMean(suggestConfigKey(key)));
  return valueText(*k, config, false);
}

std::string configValueToml(const RunConfig& config, std::string_view key) {
  const KeyInfo* k = findKey(key);
  if (!k) throw Error("unknown key '" + std::string(key) + "'" + didYouMean(suggestConfigKey(key)));
  return valueText(*k, config, true);
}

bool isRealKey(std::string_view key) {
  const KeyInfo* k = findKey(key);
  return k && k->kind == Kind::Number;
}

void applySetting(RunConfig& config, const std::string& key, const toml::node& value,
                  const std::string& where) {
  const KeyInfo* k = findKey(key);
  if (!k) {
    throw Error(where + ": unknown key '" + key + "'" + didYouMean(suggestConfigKey(key)));
  }
  const std::string head = where + ": " + key + " = " + nodeText(value, true) + ": ";
  auto typeError = [&](std::string_view expected) {
    return Error(head + "expected " + std::string(expected) + ", got " + typeName(value));
  };
  auto readNumber = [&](const toml::node& n, double& out) {
    // Integers are accepted where a real number is expected (period = 5).
    if (const auto* i = n.as_integer()) {
      out = static_cast<double>(i->get());
      return true;
    }
    if (const auto* f = n.as_floating_point()) {
      out = f->get();
      return true;
    }
    return false;
  };

  switch (k->kind) {
    case Kind::Number: {
      double v = 0.0;
      if (!readNumber(value, v)) throw typeError("a number");
      if (const std::string p = rangeProblem(v, k->lower, k->upper); !p.empty()) throw Error(head + p);
      k->number(config) = v;
      return;
    }
    case Kind::Integer: {
      const auto* i = value.as_integer();
      if (!i) throw typeError("an integer");
      const std::string p = rangeProblem(static_cast<double>(i->get()), k->lower, k->upper);
      if (i->get() < 0 || !p.empty()) throw Error(head + (p.empty() ? "must be >= 0" : p));
      k->integer(config) = static_cast<std::uint64_t>(i->get());
      return;
    }
    case Kind::Boolean: {
      const auto* b = value.as_boolean();
      if (!b) throw typeError("true or false");
      k->boolean(config) = b->get();
      return;
    }
    case Kind::Text: {
      const auto* s = value.as_string();
      if (!s) throw typeError("a string");
      k->text(config) = s->get();
      return;
    }
    case Kind::Choice: {
      const auto* s = value.as_string();
      const std::string options = joinedNames(k->choices);
      if (!s) throw typeError("one of " + options);
      if (std::find(k->choices.begin(), k->choices.end(), s->get()) == k->choices.end()) {
        throw Error(head + "must be one of " + options);
      }
      choose(*k, config, s->get());
      return;
    }
    case Kind::NumberList: {
      const auto* a = value.as_array();
      if (!a) throw typeError("an array of numbers");
      std::vector<double> out;
      for (std::size_t i = 0; i < a->size(); ++i) {
        double v = 0.0;
        if (!readNumber(*a->get(i), v)) {
          throw Error(head + "element " + std::to_string(i + 1) + ": expected a number, got " +
                      typeName(*a->get(i)));
        }
        if (const std::string p = rangeProblem(v, k->lower, k->upper); !p.empty()) {
          throw Error(head + "element " + std::to_string(i + 1) + " " + p);
        }
        out.push_back(v);
      }
      k->numberList(config) = std::move(out);
      return;
    }
    case Kind::PointList: {
      const auto* a = value.as_array();
      if (!a) throw typeError("an array of [x, y] pairs");
      Points out;
      for (std::size_t i = 0; i < a->size(); ++i) {
        const auto* pair = a->get(i)->as_array();
        std::array<double, 2> p{};
        if (!pair || pair->size() != 2 || !readNumber(*pair->get(0), p[0]) ||
            !readNumber(*pair->get(1), p[1])) {
          throw Error(head + "element " + std::to_string(i + 1) + ": expected an [x, y] pair of numbers");
        }
        if (!std::isfinite(p[0]) || !std::isfinite(p[1])) {
          throw Error(head + "element " + std::to_string(i + 1) + " must be finite");
        }
        out.push_back(p);
      }
      k->pointList(config) = std::move(out);
      return;
    }
  }
}

toml::table parseTomlText(const std::string& tomlText, const std::string& sourceName) {
  try {
    return toml::parse(tomlText, sourceName);
  } catch (const toml::parse_error& e) {
    const auto& b = e.source().begin;
    throw Error(sourceName + ":" + std::to_string(b.line) + ":" + std::to_string(b.column) +
                ": TOML syntax error: " + std::string(e.description()));
  }
}

std::vector<ConfigEntry> configEntries(const toml::table& table, const std::string& sourceName,
                                       const std::string& tablePath,
                                       const std::vector<std::string>& skipNames) {
  // toml++ keeps a table's keys sorted by name; walk them in file order so that the first problem
  // reported is the first one in the file and sweep grids vary in the order written.
  auto byPosition = [](const toml::node* a, const toml::node* b) {
    const auto pa = a->source().begin, pb = b->source().begin;
    return pa.line != pb.line ? pa.line < pb.line : pa.column < pb.column;
  };
  std::vector<std::pair<std::string, const toml::node*>> sections;
  for (const auto& [name, node] : table) {
    if (std::find(skipNames.begin(), skipNames.end(), name.str()) == skipNames.end()) {
      sections.emplace_back(std::string(name.str()), &node);
    }
  }
  std::stable_sort(sections.begin(), sections.end(),
                   [&](const auto& a, const auto& b) { return byPosition(a.second, b.second); });

  std::vector<ConfigEntry> out;
  for (const auto& [section, node] : sections) {
    const std::string where = lineWhere(sourceName, *node);
    if (!isSection(section)) {
      const std::string s = suggestSection(section);
      const bool isKey = !s.empty() && s.find('.') != std::string::npos;
      throw Error(where + ": unknown " + (node->is_table() && !isKey ? "section" : "key") + " '" +
                  withPath(tablePath, section) + "'" +
                  didYouMean(s, tablePath.empty() ? "" : tablePath + "."));
    }
    const toml::table* keys = node->as_table();
    if (!keys) {
      throw Error(where + ": '" + withPath(tablePath, section) + "' must be a table ([" +
                  withPath(tablePath, section) + "]), got " + typeName(*node));
    }
    std::vector<ConfigEntry> inSection;
    for (const auto& [key, value] : *keys) {
      const std::string full = section + "." + std::string(key.str());
      if (!isConfigKey(full)) {
        throw Error(lineWhere(sourceName, value) + ": unknown key '" + withPath(tablePath, full) +
                    "'" + didYouMean(suggestConfigKey(full), tablePath.empty() ? "" : tablePath + "."));
      }
      inSection.push_back({full, &value, value.source().begin.line});
    }
    std::stable_sort(inSection.begin(), inSection.end(),
                     [&](const ConfigEntry& a, const ConfigEntry& b) { return byPosition(a.value, b.value); });
    out.insert(out.end(), inSection.begin(), inSection.end());
  }
  return out;
}

void applyConfigTable(RunConfig& config, const toml::table& table, const std::string& sourceName,
                      const std::string& tablePath) {
  for (const ConfigEntry& e : configEntries(table, sourceName, tablePath)) {
    applySetting(config, e.key, *e.value,
                 e.line ? sourceName + ":" + std::to_string(e.line) : sourceName);
  }
}

RunConfig parseRunConfig(const std::string& tomlText, const std::string& sourceName) {
  RunConfig config;
  const toml::table table = parseTomlText(tomlText, sourceName);
  applyConfigTable(config, table, sourceName);
  try {
    validateRunConfig(config);
  } catch (const Error& e) {
    throw Error(sourceName + ": " + e.what());
  }
  return config;
}

void applyOverride(RunConfig& config, const std::string& assignment) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos) {
    throw Error("--set '" + assignment + "': expected section.key=value");
  }
  const std::string key = trim(std::string_view(assignment).substr(0, eq));
  const std::string text = trim(std::string_view(assignment).substr(eq + 1));
  if (!isConfigKey(key)) {
    throw Error("--set: unknown key '" + key + "'" + didYouMean(suggestConfigKey(key)));
  }
  // The value is TOML (5, "disk", [0, 5], true). Shell users drop quotes, so text that is not
  // TOML is taken as a number if it reads as one (".5"), otherwise as a bare string (triangle).
  toml::table holder;
  try {
    holder = toml::parse("v = " + text, std::string_view("--set"));
    if (holder.size() != 1 || !holder.contains("v")) throw Error("");
  } catch (const std::exception& e) {
    holder = toml::table{};
    const bool looksStructured = !text.empty() && std::string_view("[{\"'").find(text.front()) !=
                                                      std::string_view::npos;
    if (looksStructured) {
      const auto* pe = dynamic_cast<const toml::parse_error*>(&e);
      throw Error("--set " + key + "=" + text + ": not a TOML value" +
                  (pe ? ": " + std::string(pe->description()) : std::string()));
    }
    double v = 0.0;
    const auto r = std::from_chars(text.data(), text.data() + text.size(), v);
    if (!text.empty() && r.ec == std::errc() && r.ptr == text.data() + text.size()) {
      holder.insert("v", v);
    } else {
      holder.insert("v", text);
    }
  }
  applySetting(config, key, *holder.get("v"), "--set");
}

RunConfig loadRunConfig(const std::optional<std::string>& path,
                        const std::vector<std::string>& overrides) {
  RunConfig config;
  if (path) {
    const toml::table table = parseTomlText(readInputFile(*path, "config file"), *path);
    applyConfigTable(config, table, *path);
  }
  for (const std::string& o : overrides) applyOverride(config, o);
  try {
    validateRunConfig(config);
  } catch (const Error& e) {
    std::string source = path ? *path : std::string("default config");
    if (!overrides.empty()) source += " with --set";
    throw Error(source + ": " + e.what());
  }
  return config;
}

std::string firstDifferingKey(const RunConfig& a, const RunConfig& b, const std::vector<std::string_view>& ignored) {
  // TOML text is the shortest round-trip form, so equal text means equal bits (and -0 != 0).
  for (const KeyInfo& k : keyTable()) {
    if (std::find(ignored.begin(), ignored.end(), k.name) != ignored.end()) continue;
    if (valueText(k, a, true) != valueText(k, b, true)) return std::string(k.name);
  }
  return "";
}

bool sameRunConfig(const RunConfig& a, const RunConfig& b) { return firstDifferingKey(a, b).empty(); }

std::string toToml(const RunConfig& config) {
  std::string out =
      "# wiggle run configuration: every key, as resolved (defaults, then the file, then --set).\n"
      "# Units: lengths in d (mean grain diameter), times in sqrt(d/g), rho = d = g = 1.\n";
  std::string_view section;
  for (const KeyInfo& k : keyTable()) {
    if (k.section() != section) {
      section = k.section();
      out += "\n[" + std::string(section) + "]\n";
    }
    std::string line = std::string(k.leaf()) + " = " + valueText(k, config, true);
    if (line.size() < 32) line.resize(32, ' ');
    line += "  # " + std::string(k.help);
    if (!k.unit.empty()) line += " [" + std::string(k.unit) + "]";
    out += line + "\n";
  }
  return out;
}

std::string configHelp() {
  const RunConfig defaults;
  std::string out =
      "Configuration keys: TOML sections and keys, or --set section.key=value.\n"
      "Lengths in d (mean grain diameter), times in sqrt(d/g); rho = d = g = 1.\n"
      "Each line: key = default  [unit]  meaning; allowed values. (bed): the bed depends on the key, so a\n"
      "new value makes (and caches) a new bed.\n";
  std::string_view section;
  for (const KeyInfo& k : keyTable()) {
    if (k.section() != section) {
      section = k.section();
      out += "\n[" + std::string(section) + "]\n";
    }
    std::string line = "  " + std::string(k.leaf()) + " = " + valueText(k, defaults, true);
    if (line.size() < 30) line.resize(30, ' ');
    line += "  ";
    std::string unit = k.unit.empty() ? "" : "[" + std::string(k.unit) + "]";
    if (unit.size() < 11) unit.resize(11, ' ');
    line += unit + "  " + std::string(k.help);
    std::string allowed;
    switch (k.kind) {
      case Kind::Number:
      case Kind::Integer:
        if (k.lower.present || k.upper.present) allowed = "must be " + boundText(k.lower, k.upper);
        break;
      case Kind::Choice:
        for (const std::string_view c : k.choices) allowed += (allowed.empty() ? "one of " : " | ") + std::string(c);
        break;
      default: break;
    }
    if (!allowed.empty()) line += "; " + allowed;
    if (k.bed == BedRole::Shapes) line += " (bed)";
    out += line + "\n";
  }
  return out;
}

}  // namespace wiggle
