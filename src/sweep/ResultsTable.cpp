#include "sweep/ResultsTable.h"

#include <algorithm>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "core/Error.h"
#include "core/Format.h"
#include "io/AtomicFile.h"
#include "io/Config.h"
#include "scenario/RunSummary.h"

namespace wiggle {

namespace {

// The parameters the plots know by meaning (python/wiggleplot/prepare.py): always present.
constexpr const char* kAlwaysKeys[] = {"intruder.shape", "drive.amplitude", "drive.period", "contact.mu", "box.seed"};

// A [[case]] label comes from SweepSpec under the key "case", which results.csv already uses for
// the case's full name; its column is called case_label instead.
std::string columnName(const std::string& key) { return key == "case" ? "case_label" : key; }

std::vector<std::string> parameterKeys(const SweepSpec& spec) {
  std::vector<std::string> keys = spec.parameterKeys;
  for (const char* k : kAlwaysKeys)
    if (std::find(keys.begin(), keys.end(), k) == keys.end()) keys.emplace_back(k);
  return keys;
}

}  // namespace

std::string csvCell(const std::string& text);

namespace {
void appendRow(std::string& out, const std::vector<std::string>& cells) {
  for (std::size_t i = 0; i < cells.size(); ++i) {
    if (i) out += ',';
    out += csvCell(cells[i]);
  }
  out += '\n';
}
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

bool caseFinished(const std::string& runDir) {
  try {
    return readCaseSummary(runDir).status == "ok";
  } catch (const Error&) {
    return false;
  }
}

std::string joinedWarnings(const std::vector<std::string>& warnings) {
  std::string out;
  for (const std::string& w : warnings) out += (out.empty() ? "" : " | ") + w;
  return out;
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
  if (summary.status != "ok") {
    r.status = "failed";
    r.error = path + " has status '" + summary.status + "'";
    return r;
  }
  r.status = "ok";
  r.vy = summary.vy;
  r.vySlope = summary.vySlope;
  r.wallSeconds = summary.wallSeconds;
  r.nsPerParticleStep = summary.nsPerParticleStep;
  r.runWallSeconds = summary.runWallSeconds;
  r.grains = summary.grains;
  r.steps = summary.steps;
  const double particles = summary.particles ? static_cast<double>(summary.particles) : static_cast<double>(r.grains);
  r.particleSteps = particles * static_cast<double>(r.steps);
  r.stateHash = summary.stateHash;
  r.warnings = summary.warnings;
  return r;
}

std::vector<std::string> resultColumns(const SweepSpec& spec) {
  std::vector<std::string> columns = {"case", "run_dir", "status", "vy", "vy_slope", "wall_s"};
  for (const std::string& k : parameterKeys(spec)) columns.push_back(columnName(k));
  for (const char* k : {"n_grains", "steps", "ns_per_particle_step", "state_hash", "error", "warnings"})
    columns.emplace_back(k);
  return columns;
}

std::string resultsCsv(const SweepSpec& spec, const std::vector<std::string>& runDirs,
                       const std::vector<CaseResult>& results) {
  if (runDirs.size() != spec.cases.size() || results.size() != spec.cases.size())
    throw Error("results.csv: internal error: one run directory and result per case expected");
  std::string out;
  const std::vector<std::string> columns = resultColumns(spec);
  appendRow(out, columns);
  const std::vector<std::string> keys = parameterKeys(spec);
  for (std::size_t c = 0; c < spec.cases.size(); ++c) {
    const SweepCase& sc = spec.cases[c];
    const CaseResult& r = results[c];
    const bool ok = r.status == "ok";
    std::vector<std::string> row = {sc.name, runDirs[c], r.status, ok ? formatNumber(r.vy, 10) : "",
                                    ok ? formatNumber(r.vySlope, 10) : "", ok ? formatNumber(r.wallSeconds, 10) : ""};
    for (const std::string& k : keys) {
      std::string value;
      for (const SweepParameter& p : sc.parameters)
        if (p.key == k) value = p.value;
      if (value.empty() && k != "case") value = configValueString(sc.config, k);
      row.push_back(value);
    }
    row.push_back(ok ? std::to_string(r.grains) : "");
    row.push_back(ok ? std::to_string(r.steps) : "");
    row.push_back(ok ? formatNumber(r.nsPerParticleStep, 10) : "");
    row.push_back(ok ? r.stateHash : "");
    row.push_back(r.error);
    row.push_back(ok ? joinedWarnings(r.warnings) : "");
    appendRow(out, row);
  }
  return out;
}

}  // namespace wiggle
