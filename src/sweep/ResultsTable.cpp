#include "sweep/ResultsTable.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "core/Error.h"
#include "core/Format.h"
#include "core/Median.h"
#include "io/AtomicFile.h"
#include "io/Config.h"
#include "scenario/run/RunSummary.h"

namespace wiggle {

namespace {

// The parameters the plots know by meaning (python/wiggleplot/prepare.py): always present.
constexpr const char* kAlwaysKeys[] = {"intruder.shape", "drive.amplitude", "drive.period", "contact.mu", "box.seed"};

}  // namespace

// A [[case]] label comes from SweepSpec under the key "case", which results.csv already uses for
// the case's full name; its column is called case_label instead.
std::string resultParameterColumn(const std::string& key) { return key == "case" ? "case_label" : key; }

std::vector<std::string> resultParameterKeys(const SweepSpec& spec) {
  std::vector<std::string> keys = spec.parameterKeys;
  for (const char* k : kAlwaysKeys)
    if (std::find(keys.begin(), keys.end(), k) == keys.end()) keys.emplace_back(k);
  return keys;
}

std::string resultParameterValue(const SweepCase& sc, const std::string& key) {
  for (const SweepParameter& p : sc.parameters)
    if (p.key == key) return p.value;
  return key == "case" ? std::string() : configValueString(sc.config, key);
}

std::string csvCell(const std::string& text);

std::string csvRow(const std::vector<std::string>& cells) {
  std::string out;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    if (i) out += ',';
    out += csvCell(cells[i]);
  }
  return out + '\n';
}

namespace {
void appendRow(std::string& out, const std::vector<std::string>& cells) { out += csvRow(cells); }
}  // namespace

std::string csvCell(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string out = "\"";
  for (const char ch : text) {
    if (ch == '"') out += '"';
    out += ch;
  }
  return out + '"';
}

std::string interruptedError(const std::string& why) {
  return why.starts_with("interrupted") ? why : "interrupted: " + why;
}

CaseStatus caseStatusNamed(std::string_view word, const std::string& where) {
  if (const std::optional<CaseStatus> status = choiceNamed<CaseStatus>(word)) return *status;
  throw Error(where + ": status '" + std::string(word) + "' is none of " + joinedNames(choiceNameList<CaseStatus>()));
}

bool caseFinished(const std::string& runDir) {
  try {
    return readCaseSummary(runDir).status == CaseStatus::Ok;
  } catch (const Error&) {
    return false;
  }
}

std::string joinedWarnings(const std::vector<std::string>& warnings) {
  std::string out;
  for (const std::string& w : warnings) out += (out.empty() ? "" : " | ") + w;
  return out;
}

double sweepNsPerParticleStep(const std::vector<CaseResult>& results, std::optional<std::size_t> only,
                              double fallback) {
  std::vector<double> each;
  for (std::size_t c = 0; c < results.size(); ++c) {
    const CaseResult& r = results[c];
    if ((!only || c == *only) && r.status == CaseStatus::Ok && r.particleSteps() > 0.0)
      each.push_back(1e9 * r.summary.runWallSeconds / r.particleSteps());
  }
  return each.empty() ? fallback : median(std::move(each));
}

CaseResult readCaseSummary(const std::string& runDir) {
  const std::string path = runDir + "/summary.json";
  RunSummary summary;
  try {
    summary = summaryFromJson(nlohmann::json::parse(readFile(path)));
  } catch (const nlohmann::json::exception& e) {
    throw Error(path + " is not valid JSON: " + e.what());
  } catch (const Error& e) {
    throw Error(path + ": " + e.what());
  }
  CaseResult r;
  if (summary.status != RunStatus::Ok) {
    r.status = CaseStatus::Failed;
    r.error = path + " has status '" + std::string(choiceName(summary.status)) + "'";
    return r;
  }
  r.status = CaseStatus::Ok;
  r.summary = std::move(summary);
  return r;
}

double CaseResult::particleSteps() const {
  const std::uint64_t particles = summary.particles ? summary.particles : summary.grains;
  return static_cast<double>(particles) * static_cast<double>(summary.steps);
}

namespace {

// A case's number: empty unless the case is ok.
std::string okNumber(const ResultRow& row, double value) {
  return row.result.status == CaseStatus::Ok ? formatNumber(value, 10) : std::string();
}
std::string okText(const ResultRow& row, const std::string& text) {
  return row.result.status == CaseStatus::Ok ? text : std::string();
}

}  // namespace

const std::vector<ResultColumn>& resultColumnsBeforeParameters() {
  static const std::string statusWords = joinedNames(choiceNameList<CaseStatus>(), " | ");  // the schema's meaning
  static const std::vector<ResultColumn> columns = {
      {"case", "", "the case's name (its run directory's)", [](const ResultRow& r) { return r.sweepCase.name; }},
      {"run_dir", "", "the case's run directory, relative to the sweep directory",
       [](const ResultRow& r) { return r.runDir; }},
      {"status", "", statusWords.c_str(), [](const ResultRow& r) { return std::string(choiceName(r.result.status)); }},
      {"vy", "sqrt(g d)", "the rise rate by the run's rule (summary.json's vy)",
       [](const ResultRow& r) { return okNumber(r, r.result.summary.vy); }},
      {"vy_slope", "sqrt(g d)", "the least-squares slope of y(t) over the same window",
       [](const ResultRow& r) { return okNumber(r, r.result.summary.vySlope); }},
      {"vy_settled", "sqrt(g d)", "the rise rate by the paper's t_f rule",
       [](const ResultRow& r) { return okNumber(r, r.result.summary.vySettled); }},
      {"t_settled", "sqrt(d/g)", "the t_f that rule chose",
       [](const ResultRow& r) { return okNumber(r, r.result.summary.tSettled); }},
      {"wall_s", "s", "the case's wall time, bed included",
       [](const ResultRow& r) { return okNumber(r, r.result.summary.wallSeconds); }},
  };
  return columns;
}

const std::vector<ResultColumn>& resultColumnsAfterParameters() {
  static const std::vector<ResultColumn> columns = {
      {"n_grains", "", "mobile grains in the bed",
       [](const ResultRow& r) { return okText(r, std::to_string(r.result.summary.grains)); }},
      {"steps", "", "time steps run", [](const ResultRow& r) { return okText(r, std::to_string(r.result.summary.steps)); }},
      {"ns_per_particle_step", "ns", "stepping cost: wall time per particle per step",
       [](const ResultRow& r) { return okNumber(r, r.result.summary.nsPerParticleStep); }},
      {"state_hash", "", "the hash of the final state (summary.json's state_hash)",
       [](const ResultRow& r) { return okText(r, r.result.summary.stateHash); }},
      {"error", "", "why the case failed or stopped, in one line", [](const ResultRow& r) { return r.result.error; }},
      {"warnings", "", "summary.json's warnings joined by \" | \"",
       [](const ResultRow& r) { return okText(r, joinedWarnings(r.result.summary.warnings)); }},
  };
  return columns;
}

nlohmann::json resultsSchema() {
  auto list = [](const std::vector<ResultColumn>& columns) {
    nlohmann::json out = nlohmann::json::array();
    for (const ResultColumn& c : columns) out.push_back({{"name", c.name}, {"unit", c.unit}, {"meaning", c.meaning}});
    return out;
  };
  return {{"before_parameters", list(resultColumnsBeforeParameters())},
          {"parameters",
           "one column per parameter, named by its config key: the keys that vary in the sweep, then "
           "intruder.shape, drive.amplitude, drive.period, contact.mu and box.seed when they do not; a [[case]]'s "
           "own label is the column case_label"},
          {"after_parameters", list(resultColumnsAfterParameters())}};
}

std::vector<std::string> resultColumns(const SweepSpec& spec) {
  std::vector<std::string> columns;
  for (const ResultColumn& c : resultColumnsBeforeParameters()) columns.emplace_back(c.name);
  for (const std::string& k : resultParameterKeys(spec)) columns.push_back(resultParameterColumn(k));
  for (const ResultColumn& c : resultColumnsAfterParameters()) columns.emplace_back(c.name);
  return columns;
}

std::string resultsCsv(const SweepSpec& spec, const std::vector<std::string>& runDirs,
                       const std::vector<CaseResult>& results) {
  if (runDirs.size() != spec.cases.size() || results.size() != spec.cases.size())
    throw Error("results.csv: internal error: one run directory and result per case expected");
  std::string out;
  appendRow(out, resultColumns(spec));
  const std::vector<std::string> keys = resultParameterKeys(spec);
  for (std::size_t c = 0; c < spec.cases.size(); ++c) {
    const SweepCase& sc = spec.cases[c];
    const ResultRow source{sc, runDirs[c], results[c]};
    std::vector<std::string> row;
    for (const ResultColumn& column : resultColumnsBeforeParameters()) row.push_back(column.cell(source));
    for (const std::string& k : keys) row.push_back(resultParameterValue(sc, k));
    for (const ResultColumn& column : resultColumnsAfterParameters()) row.push_back(column.cell(source));
    appendRow(out, row);
  }
  return out;
}

std::vector<std::vector<std::string>> parseCsv(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::vector<std::string> row;
  std::string cell;
  bool quoted = false, any = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (quoted) {
      if (c == '"' && i + 1 < text.size() && text[i + 1] == '"') {
        cell += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        cell += c;
      }
    } else if (c == '"') {
      quoted = any = true;
    } else if (c == ',') {
      row.push_back(std::move(cell));
      cell.clear();
      any = true;
    } else if (c == '\n') {
      row.push_back(std::move(cell));
      cell.clear();
      rows.push_back(std::move(row));
      row.clear();
      any = false;
    } else if (c != '\r') {
      cell += c;
      any = true;
    }
  }
  if (any || !cell.empty()) {
    row.push_back(std::move(cell));
    rows.push_back(std::move(row));
  }
  return rows;
}

std::map<std::string, CaseResult> readUnfinishedRows(const std::string& sweepDir) {
  const std::string path = sweepDir + "/results.csv";
  std::map<std::string, CaseResult> unfinished;
  try {
    if (!std::filesystem::exists(path)) return {};
    const std::vector<std::vector<std::string>> rows = parseCsv(readFile(path));
    if (rows.empty()) return {};
    const std::vector<std::string>& header = rows.front();
    const auto column = [&](const char* name) {
      const auto it = std::find(header.begin(), header.end(), name);
      if (it == header.end()) throw Error(path + ": no column '" + name + "'");
      return static_cast<std::size_t>(it - header.begin());
    };
    const std::size_t nameAt = column("case"), statusAt = column("status"), errorAt = column("error");
    for (std::size_t r = 1; r < rows.size(); ++r) {
      const std::vector<std::string>& row = rows[r];
      if (row.size() != header.size()) throw Error(path + ": row " + std::to_string(r + 1) + " is short");
      CaseResult result;
      result.status = caseStatusNamed(row[statusAt], path + ": row " + std::to_string(r + 1));
      result.error = row[errorAt];
      if (result.status != CaseStatus::Ok) unfinished[row[nameAt]] = std::move(result);
    }
  } catch (const Error&) {
    return {};  // torn or foreign: the caller's own view stands
  }
  return unfinished;
}

void refreshSettledColumns(const std::string& sweepDir) {
  const std::string path = sweepDir + "/results.csv";
  std::vector<std::vector<std::string>> rows = parseCsv(readFile(path));
  if (rows.empty()) throw Error(path + " is empty");
  std::vector<std::string>& header = rows[0];
  auto column = [&](const std::string& name) {
    return static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin());
  };
  if (column("vy_settled") == header.size()) {
    const std::size_t after = column("vy_slope");
    if (after == header.size()) throw Error(path + " has no vy_slope column: not a wiggle results table");
    for (auto& row : rows)
      if (row.size() > after) row.insert(row.begin() + static_cast<std::ptrdiff_t>(after) + 1, 2, std::string());
    header[after + 1] = "vy_settled";
    header[after + 2] = "t_settled";
  }
  const std::size_t runDir = column("run_dir"), status = column("status");
  const std::size_t vySettled = column("vy_settled"), tSettled = column("t_settled");
  if (runDir == header.size() || status == header.size() || tSettled == header.size())
    throw Error(path + " lacks the run_dir, status or t_settled column: not a wiggle results table");
  std::string out;
  appendRow(out, header);
  for (std::size_t r = 1; r < rows.size(); ++r) {
    std::vector<std::string>& row = rows[r];
    if (row.size() != header.size())
      throw Error(path + ": row " + std::to_string(r + 1) + " has " + std::to_string(row.size()) +
                  " cells, the header " + std::to_string(header.size()));
    if (caseStatusNamed(row[status], path + ": row " + std::to_string(r + 1)) == CaseStatus::Ok) {
      const CaseResult result = readCaseSummary(sweepDir + "/" + row[runDir]);
      row[vySettled] = formatNumber(result.summary.vySettled, 10);
      row[tSettled] = formatNumber(result.summary.tSettled, 10);
    }
    appendRow(out, row);
  }
  writeFileAtomically(path, out);
}

}  // namespace wiggle
