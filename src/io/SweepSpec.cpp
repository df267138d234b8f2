#include "io/SweepSpec.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <map>

#include "core/Error.h"
#include "core/Hash.h"
#include "io/AtomicFile.h"
#include "io/Config.h"

namespace wiggle {
namespace {

// A typo like 1e6 values in a grid should not eat RAM and minutes before anything runs: a million
// cases took over 10 s and about 1 GB to expand (found by fuzzing, tests/data/bad_sweeps/
// fuzz_timeout_968968_cases.toml); 100,000 DEM cases are far beyond any real study.
constexpr std::size_t maxCases = 100000;

// Text made safe for a directory name: letters, digits and . + - kept (and _ = when
// `keepSeparators`), any other run of characters becomes one '_'. Long or empty results become a
// hash of the text, which is just as stable.
std::string sanitize(const std::string& text, bool keepSeparators) {
  std::string out;
  for (const char ch : text) {
    const bool ok = std::isalnum(static_cast<unsigned char>(ch)) || ch == '.' || ch == '+' ||
                    ch == '-' || (keepSeparators && (ch == '_' || ch == '='));
    if (ok) {
      out += ch;
    } else if (!out.empty() && out.back() != '_') {
      out += '_';
    }
  }
  while (!out.empty() && out.back() == '_') out.pop_back();
  if (out.empty() || out.size() > 40) {
    Hasher h;
    h.addBytes(text.data(), text.size());
    out = 'h';  // (not "h" + string: GCC 12 warns falsely, -Wrestrict)
    out += h.hex().substr(0, 8);
  }
  return out;
}

std::string suggestTopLevel(const std::string& name) {
  for (const char* s : {"sweep", "base", "grid", "case"}) {
    std::size_t diff = 0;  // tiny edit distance: same length and at most one letter changed,
    if (name.size() == std::char_traits<char>::length(s)) {  // or a plural
      for (std::size_t i = 0; i < name.size(); ++i) diff += name[i] != s[i];
      if (diff <= 1) return s;
    }
    if (name == std::string(s) + "s") return s;
  }
  // A run-config section at the top level belongs under [base] (or [grid]).
  for (const std::string& key : configKeys()) {
    if (key.rfind(name + ".", 0) == 0) return "base." + name;
  }
  return "";
}

struct CaseSource {
  std::string label;                 // explicit `name`, or built from its own values
  std::string cellLabel;             // the same without its seed (the cell's part of the name)
  bool named = false;
  std::vector<ConfigEntry> entries;  // its keys, file order
};

std::string lineTag(const ConfigEntry& e, const char* table) {
  return (e.line ? "line " + std::to_string(e.line) + " " : std::string()) + table;
}

}  // namespace

namespace {

// The file's top-level tables: [sweep], [base], [grid] and the [[case]] list; anything else is an
// error naming it.
struct SweepTables {
  const toml::table* base = nullptr;
  const toml::table* grid = nullptr;
  const toml::array* cases = nullptr;
};

SweepTables topLevelTables(const toml::table& root, const std::string& sourceName) {
  SweepTables tables;
  for (const auto& [keyName, node] : root) {
    const std::string key(keyName.str());
    const std::string where = sourceName + ":" + std::to_string(node.source().begin.line);
    if (key == "base" || key == "grid" || key == "sweep") {
      if (!node.is_table()) throw Error(where + ": '" + key + "' must be a table ([" + key + "])");
      if (key == "base") tables.base = node.as_table();
      if (key == "grid") tables.grid = node.as_table();
    } else if (key == "case") {
      tables.cases = node.as_array();
      if (!tables.cases || !tables.cases->is_array_of_tables()) {
        throw Error(where + ": 'case' must be a list of tables ([[case]])");
      }
    } else {
      const std::string s = suggestTopLevel(key);
      throw Error(where + ": unknown table '" + key + "'" +
                  (s.empty() ? " (a sweep file has [sweep], [base], [grid] and [[case]])"
                             : " (did you mean '" + s + "'?)"));
    }
  }
  return tables;
}

// [sweep]: name, jobs, threads_per_case.
void readSweepSettings(const toml::table& root, const std::string& sourceName, SweepSettings& settings) {
  const toml::table* sweep = root["sweep"].as_table();
  if (!sweep) return;
  for (const auto& [keyName, node] : *sweep) {
    const std::string key(keyName.str());
    const std::string where = sourceName + ":" + std::to_string(node.source().begin.line) + ": sweep." + key +
                              " = " + tomlValueString(node);
    if (key == "name") {
      const auto* s = node.as_string();
      if (!s) throw Error(where + ": expected a string");
      settings.name = s->get();
    } else if (key == "beds") {
      // Replicates: how many beds every case runs on (box.seed 1..N, or a box.seed grid's seeds).
      const auto* i = node.as_integer();
      if (!i) throw Error(where + ": expected an integer (the beds of every case, e.g. beds = 3)");
      if (i->get() < 1 || i->get() > 1000) throw Error(where + ": must be from 1 to 1000 (the beds of every case)");
      settings.beds = static_cast<int>(i->get());
    } else if (key == "jobs" || key == "threads_per_case") {
      const auto* i = node.as_integer();
      if (!i) throw Error(where + ": expected an integer");
      if (i->get() < 0 || i->get() > 1000000) throw Error(where + ": must be >= 0 (0 = automatic)");
      (key == "jobs" ? settings.jobs : settings.threadsPerCase) = static_cast<int>(i->get());
    } else {
      throw Error(sourceName + ":" + std::to_string(node.source().begin.line) + ": unknown key 'sweep." + key +
                  "' (known: name, jobs, threads_per_case, beds)");
    }
  }
}

// [grid]: every leaf a non-empty array; returns the number of combinations.
std::size_t checkGrid(const std::vector<ConfigEntry>& grid, const std::string& sourceName) {
  std::size_t combinations = 1;
  for (const ConfigEntry& g : grid) {
    const std::string where = sourceName + ":" + std::to_string(g.line) + ": grid." + g.key;
    const auto* values = g.value->as_array();
    if (!values) {
      throw Error(where + ": expected an array of values (e.g. [1, 5]), got " + tomlValueString(*g.value));
    }
    if (values->empty()) throw Error(where + ": empty array, which gives no cases");
    combinations *= values->size();
    if (combinations > maxCases) throw Error(where + ": the grid has more than " + std::to_string(maxCases) + " cases");
  }
  return combinations;
}

// [[case]]: each table's name (or one made of its settings) and settings, none also in [grid].
std::vector<CaseSource> readCases(const toml::array& caseArray, const std::vector<ConfigEntry>& grid,
                                  std::size_t combinations, const std::string& sourceName) {
  std::vector<CaseSource> cases;
  for (std::size_t i = 0; i < caseArray.size(); ++i) {
    const toml::table& t = *caseArray.get(i)->as_table();
    CaseSource c;
    if (const toml::node* n = t.get("name")) {
      const auto* s = n->as_string();
      if (!s) {
        throw Error(sourceName + ":" + std::to_string(n->source().begin.line) + ": case " + std::to_string(i + 1) +
                    ": name must be a string");
      }
      c.label = s->get();
      c.named = true;
    }
    c.entries = configEntries(t, sourceName, "case", {"name"});
    if (!c.named) {
      for (const ConfigEntry& e : c.entries) {
        std::string part = e.key.substr(e.key.find('.') + 1) + '=' + sanitize(tomlValueString(*e.value), false);
        c.label += c.label.empty() ? part : "_" + part;
        if (e.key != kBedKey) c.cellLabel += c.cellLabel.empty() ? part : "_" + part;
      }
      if (c.label.empty()) c.label = "case" + std::to_string(i + 1);
    } else {
      c.cellLabel = c.label;
    }
    for (const ConfigEntry& e : c.entries) {
      for (const ConfigEntry& g : grid) {
        if (g.key == e.key) {
          throw Error(sourceName + ": " + e.key + " is set both in [[case]] " + std::to_string(i + 1) + " (line " +
                      std::to_string(e.line) + ") and in [grid] (line " + std::to_string(g.line) + ")");
        }
      }
    }
    cases.push_back(std::move(c));
  }
  if (cases.size() * combinations > maxCases) throw Error(sourceName + ": more than " + std::to_string(maxCases) + " cases");
  return cases;
}

// The parameter columns: "case" (when some [[case]] has a name), the keys the cases set (first seen
// first), then the grid keys in file order.
std::vector<std::string> parameterKeysOf(const std::vector<CaseSource>& cases, const std::vector<ConfigEntry>& grid) {
  std::vector<std::string> keys;
  if (std::any_of(cases.begin(), cases.end(), [](const CaseSource& c) { return c.named; })) keys.push_back("case");
  for (const CaseSource& c : cases) {
    for (const ConfigEntry& e : c.entries) {
      if (std::find(keys.begin(), keys.end(), e.key) == keys.end()) keys.push_back(e.key);
    }
  }
  for (const ConfigEntry& g : grid) keys.push_back(g.key);
  return keys;
}

// sweep.beds = N: every case on N beds. Without a [grid] box.seed the grid gains box.seed = [1..N]
// at its end (`seeds` holds those values; the seed varies fastest, so a cell's beds run one after
// another); with one, its seeds are the beds and must number N. A seed set anywhere else would
// contradict the beds, and is refused naming both.
void addBeds(int beds, const toml::table* base, const std::vector<CaseSource>& cases, std::vector<ConfigEntry>& grid,
             toml::array& seeds, const std::string& sourceName) {
  const std::string what = "sweep.beds = " + std::to_string(beds);
  for (const ConfigEntry& g : grid) {
    if (g.key != kBedKey) continue;
    const std::size_t listed = g.value->as_array()->size();
    if (listed != static_cast<std::size_t>(beds))
      throw Error(sourceName + ":" + std::to_string(g.line) + ": " + what + " but [grid] box.seed lists " +
                  std::to_string(listed) + " seed" + (listed == 1 ? "" : "s") +
                  ": with a box.seed grid its seeds are the beds; make the two agree or drop one");
    return;
  }
  for (std::size_t i = 0; i < cases.size(); ++i)
    for (const ConfigEntry& e : cases[i].entries)
      if (e.key == kBedKey)
        throw Error(sourceName + ":" + std::to_string(e.line) + ": " + what + " gives every case box.seed 1.." +
                    std::to_string(beds) + ", but [[case]] " + std::to_string(i + 1) +
                    " sets box.seed: list the seeds in [grid] box.seed instead, or drop sweep.beds");
  if (base) {
    if (const toml::node* seed = (*base)["box"]["seed"].node())
      throw Error(sourceName + ":" + std::to_string(seed->source().begin.line) + ": " + what +
                  " gives every case box.seed 1.." + std::to_string(beds) + ", but [base] sets box.seed = " +
                  tomlValueString(*seed) + ": list the seeds in [grid] box.seed instead, or drop sweep.beds");
  }
  for (int b = 1; b <= beds; ++b) seeds.push_back(static_cast<int64_t>(b));
  grid.push_back(ConfigEntry{kBedKey, &seeds, 0});
}

// The cells: cases grouped by every parameter but the seed, in the order of their first case.
void groupCells(SweepSpec& spec, const std::vector<std::string>& cellNames) {
  std::map<std::vector<std::string>, std::size_t> cellOf;
  for (SweepCase& c : spec.cases) {
    std::vector<std::string> point;
    for (const SweepParameter& p : c.parameters)
      if (p.key != kBedKey) point.push_back(p.value);
    const auto [it, fresh] = cellOf.try_emplace(point, spec.cells.size());
    if (fresh) spec.cells.push_back(SweepCell{cellNames[c.index], {}});
    c.cell = it->second;
    spec.cells[it->second].cases.push_back(c.index);
  }
}

}  // namespace

SweepSpec parseSweepSpec(const std::string& tomlText, const std::string& sourceName) {
  const toml::table root = parseTomlText(tomlText, sourceName);
  SweepSpec spec;
  spec.settings.name = std::filesystem::path(sourceName).stem().string();
  const SweepTables tables = topLevelTables(root, sourceName);
  readSweepSettings(root, sourceName, spec.settings);

  RunConfig base;
  if (tables.base) applyConfigTable(base, *tables.base, sourceName, "base");
  std::vector<ConfigEntry> grid;
  if (tables.grid) grid = configEntries(*tables.grid, sourceName, "grid");
  std::size_t combinations = checkGrid(grid, sourceName);
  std::vector<CaseSource> cases;
  if (tables.cases) cases = readCases(*tables.cases, grid, combinations, sourceName);
  toml::array seeds;  // sweep.beds' box.seed values, when the grid has none
  if (spec.settings.beds > 0) {
    addBeds(spec.settings.beds, tables.base, cases, grid, seeds, sourceName);
    combinations = checkGrid(grid, sourceName);
    if (std::max<std::size_t>(1, cases.size()) * combinations > maxCases)
      throw Error(sourceName + ": more than " + std::to_string(maxCases) + " cases");
  }
  const bool haveCases = !cases.empty();
  if (!haveCases) cases.push_back({});  // just base
  spec.parameterKeys = parameterKeysOf(cases, grid);

  // In names a grid key is shown by its last part (period=5) unless two varying keys share it.
  std::map<std::string, int> leafCount;
  for (const std::string& k : spec.parameterKeys) ++leafCount[k.substr(k.find('.') + 1)];
  auto shortKey = [&](const std::string& k) {
    const std::string leaf = k.substr(k.find('.') + 1);
    return leafCount[leaf] > 1 ? k : leaf;
  };

  std::map<std::string, std::size_t> seenNames;
  std::vector<std::string> cellNames;  // each case's name without its seed
  std::vector<std::size_t> pick(grid.size(), 0);
  for (std::size_t ci = 0; ci < cases.size(); ++ci) {
    const CaseSource& source = cases[ci];
    std::fill(pick.begin(), pick.end(), 0);
    for (std::size_t combo = 0; combo < combinations; ++combo) {
      SweepCase out;
      out.index = spec.cases.size();

      std::string name = haveCases ? sanitize(source.label, true) : std::string();
      std::string cellName = haveCases && !source.cellLabel.empty() ? sanitize(source.cellLabel, true) : std::string();
      for (std::size_t g = 0; g < grid.size(); ++g) {
        const toml::node& v = *grid[g].value->as_array()->get(pick[g]);
        const std::string part = shortKey(grid[g].key) + '=' + sanitize(tomlValueString(v), false);
        name += name.empty() ? part : "_" + part;
        if (grid[g].key != kBedKey) cellName += cellName.empty() ? part : "_" + part;
      }
      if (name.empty()) name = "base";
      if (cellName.empty()) cellName = "base";
      out.name = name;
      cellNames.push_back(cellName);

      try {
        out.config = base;
        for (const ConfigEntry& e : source.entries) {
          applySetting(out.config, e.key, *e.value, lineTag(e, "[[case]]"));
        }
        for (std::size_t g = 0; g < grid.size(); ++g) {
          const toml::node& v = *grid[g].value->as_array()->get(pick[g]);
          applySetting(out.config, grid[g].key, v, grid[g].value == &seeds ? "sweep.beds" : lineTag(grid[g], "[grid]"));
        }
        validateRunConfig(out.config);
      } catch (const Error& e) {
        throw Error(sourceName + ": case " + std::to_string(out.index + 1) + " '" + name + "': " + e.what());
      }

      if (const auto it = seenNames.find(name); it != seenNames.end()) {
        throw Error(sourceName + ": cases " + std::to_string(it->second + 1) + " and " +
                    std::to_string(out.index + 1) + " have the same name '" + name +
                    "' (repeated values, or [[case]] tables needing distinct `name`s)");
      }
      seenNames.emplace(name, out.index);

      for (const std::string& k : spec.parameterKeys) {
        out.parameters.push_back({k, k == "case" ? source.label : configValueString(out.config, k)});
      }
      spec.cases.push_back(std::move(out));

      // Odometer: the last grid key varies fastest.
      for (std::size_t g = grid.size(); g-- > 0;) {
        if (++pick[g] < grid[g].value->as_array()->size()) break;
        pick[g] = 0;
      }
    }
  }
  groupCells(spec, cellNames);
  return spec;
}

SweepSpec loadSweepSpec(const std::string& path) { return parseSweepSpec(readInputFile(path, "sweep file"), path); }

}  // namespace wiggle
